package org.ktcs.kernel.persistence

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import org.ktcs.kernel.persistence.PersistenceFixtures.APPROVED_V6
import org.ktcs.kernel.persistence.PersistenceFixtures.APPROVED_V7
import org.ktcs.kernel.persistence.PersistenceFixtures.SAMPLES

/** openTCS's own round-trip expectations: each sample, read and written as 7.0.0, gives its approved file. */
class PlantModelFilesApprovedTest : FunSpec({
    fun rewritten(
        resource: String,
    ) = PlantModelFiles.writeToString(PlantModelFiles.read(PersistenceFixtures.path(resource)))

    fun approvedV7() = PersistenceFixtures.text(APPROVED_V7)

    test("a 7.0.0 sample is written back byte for byte as openTCS writes it") {
        rewritten("$SAMPLES/PlantModelV7.sample.xml") shouldBe approvedV7()
    }

    test("a 6.0.0 sample is written byte for byte as openTCS's approved 7.0.0 file") {
        rewritten("$SAMPLES/PlantModelV6.sample.xml") shouldBe PersistenceFixtures.text(APPROVED_V6)
    }

    test("6.0.0 and 7.0.0 samples are XML-equivalent to the approved 7.0.0 file") {
        for (sample in listOf("PlantModelV6.sample.xml", "PlantModelV7.sample.xml")) {
            canonicalXml(rewritten("$SAMPLES/$sample"), ignoreModelName = true) shouldBe
                canonicalXml(approvedV7(), ignoreModelName = true)
        }
    }

    test("a 0.0.5 sample differs from the approved file only where 0.0.5 cannot say the same") {
        val expected = approvedV7().withDifferences(sampleDifferences("2024-11-21T13:01:21Z"))
        canonicalXml(rewritten("$SAMPLES/PlantModelV005.sample.xml"), ignoreModelName = true) shouldBe
            canonicalXml(expected, ignoreModelName = true)
    }

    test("a 0.0.4 sample differs from the approved file only where 0.0.4 cannot say the same") {
        val expected = approvedV7().withDifferences(sampleDifferences("2024-11-15T13:21:40Z") + beforeMovement)
        canonicalXml(rewritten("$SAMPLES/PlantModelV004.sample.xml"), ignoreModelName = true) shouldBe
            canonicalXml(expected, ignoreModelName = true)
    }
})

/** Replaces [from] by [to] in the approved file; [why] says why the old sample holds something else. */
private data class KnownDifference(val why: String, val from: String, val to: String)

private fun String.withDifferences(differences: List<KnownDifference>): String =
    differences.fold(this) { text, difference ->
        val occurrences = Regex(Regex.escape(difference.from)).findAll(text).count()
        check(occurrences == 1) { "'${difference.why}' matches $occurrences times" }
        text.replace(difference.from, difference.to)
    }

private fun sampleDifferences(lastModified: String) = listOf(
    KnownDifference(
        "the old samples were saved at another time",
        """<property name="tcs:modelFileLastModified" value="2024-11-21T14:01:30Z"/>""",
        """<property name="tcs:modelFileLastModified" value="$lastModified"/>""",
    ),
    KnownDifference(
        "points have no maximum vehicle bounding box before 6.0.0, so they get the default one",
        """<maxVehicleBoundingBox length="700" width="600" height="500" """ +
            """referenceOffsetX="10" referenceOffsetY="20"/>""",
        """<maxVehicleBoundingBox length="1000" width="1000" height="1000" """ +
            """referenceOffsetX="0" referenceOffsetY="0"/>""",
    ),
    KnownDifference(
        "vehicles have only a length before 6.0.0; width and height default to 1000, the reference offset to 0",
        """<boundingBox length="1500" width="600" height="500" referenceOffsetX="10" referenceOffsetY="20"/>""",
        """<boundingBox length="1500" width="1000" height="1000" referenceOffsetX="0" referenceOffsetY="0"/>""",
    ),
    KnownDifference(
        "the old samples draw the path with peripheral operations on layer 1",
        """<property name="p-key" value="p-value"/>
        <pathLayout connectionType="DIRECT" layerId="0"/>""",
        """<property name="p-key" value="p-value"/>
        <pathLayout connectionType="DIRECT" layerId="1"/>""",
    ),
)

private val afterAllocation = """<peripheralOperation completionRequired="false" """ +
    """executionTrigger="AFTER_ALLOCATION" locationName="Location-0001" name="p-operation"/>"""

/** 0.0.4 also has a BEFORE_MOVEMENT operation, which becomes a second AFTER_ALLOCATION one. */
private val beforeMovement = KnownDifference(
    "the 0.0.4 sample has one more operation, triggered BEFORE_MOVEMENT",
    afterAllocation,
    "$afterAllocation\n        $afterAllocation",
)
