package org.ktcs.kernel.persistence

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.nulls.shouldBeNull
import io.kotest.matchers.nulls.shouldNotBeNull
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import io.kotest.property.checkAll
import org.ktcs.kernel.persistence.v002.V002PlantModelTO
import org.ktcs.kernel.persistence.v004.V004PlantModelTO
import org.ktcs.kernel.persistence.v7.V7PlantModelTO

/** The streaming reader gives exactly Jackson's transfer objects, or leaves the file to Jackson. */
class StreamingModelReaderTest : FunSpec({
    fun typeOf(bytes: ByteArray): Class<*> = when (peekHeader(bytes, "test").version) {
        "0.0.2", "0.0.3" -> V002PlantModelTO::class.java
        "0.0.4", "0.0.5" -> V004PlantModelTO::class.java
        else -> V7PlantModelTO::class.java
    }

    fun jackson(bytes: ByteArray, warnings: ReadWarnings = ReadWarnings("test")): Any =
        ModelXml.mapper.readerFor(typeOf(bytes)).withHandler(warnings.handler).readValue(bytes)

    fun streaming(bytes: ByteArray): Any? = StreamingModelReader.read(bytes, typeOf(bytes))

    val fixtures = PersistenceFixtures.openTcsModels + PersistenceFixtures.HANDWRITTEN_V002

    test("every fixture plant Jackson reads without warnings is read to the same transfer objects") {
        for (fixture in fixtures) {
            val bytes = PersistenceFixtures.path(fixture).toFile().readBytes()
            val warnings = ReadWarnings(fixture)
            val expected = jackson(bytes, warnings)

            if (warnings.all().isEmpty()) streaming(bytes) shouldBe expected else streaming(bytes).shouldBeNull()
        }
    }

    test("openTCS's demo plants, 0.0.3 and 7.0.0, are read without Jackson") {
        for (fixture in listOf(PersistenceFixtures.DEMO_5_0, PersistenceFixtures.DEMO_HEAD)) {
            val bytes = PersistenceFixtures.path(fixture).toFile().readBytes()
            streaming(bytes).shouldNotBeNull() shouldBe jackson(bytes)
        }
    }

    test("every file kTCS writes is read to the same transfer objects as Jackson reads") {
        checkAll(200, PlantModelArbs.plantModel) { model ->
            val bytes = PlantModelFiles.writeToString(model).encodeToByteArray()
            streaming(bytes).shouldNotBeNull() shouldBe jackson(bytes)
        }
    }

    test("what Jackson would warn about or refuse is left to Jackson") {
        val demo = PersistenceFixtures.text(PersistenceFixtures.DEMO_HEAD)
        val point = """<point name="Point-0001" positionX="31000" positionY="11000""""
        val changed = listOf(
            demo.replace(point, """$point color="red""""),
            demo.replace(point, """<point name="Point-0001" positionY="11000""""),
            demo.replace(point, """<point name="Point-0001" positionX="3.1e4" positionY="11000""""),
            demo.replace(point, """<point name="Point-0001" positionX="31000" positionY="11000" type="HALT""""),
            demo.replace("</model>", "<unknownElement/></model>"),
        )
        for (text in changed) {
            (text != demo) shouldBe true
            streaming(text.encodeToByteArray()).shouldBeNull()
        }
    }

    test("a required attribute left out is reported as before, or read as Jackson reads it") {
        val demo = PersistenceFixtures.text(PersistenceFixtures.DEMO_HEAD)
        val noSource = demo.replaceFirst(Regex(""" sourcePoint="[^"]+""""), "")
        val noPosition = demo.replaceFirst(Regex(""" positionX="[-0-9]+""""), "")

        val error = runCatching { PlantModelFiles.read(noSource.byteInputStream(), "bad.xml") }.exceptionOrNull()

        error.shouldNotBeNull().message shouldContain "<path> lacks the required attribute or element \"sourcePoint\""
        val bytes = noPosition.encodeToByteArray()
        streaming(bytes)?.let { it shouldBe jackson(bytes) }
    }
})
