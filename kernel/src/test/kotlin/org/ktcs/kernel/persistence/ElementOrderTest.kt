package org.ktcs.kernel.persistence

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldContainExactly
import io.kotest.matchers.shouldBe

/** The reader takes a vehicle's child elements in any order, as openTCS does. */
class ElementOrderTest : FunSpec({
    fun read(xml: String) = PlantModelFiles.readWithWarnings(xml.byteInputStream(), "test.xml")

    val box = """<boundingBox length="1000" width="1000" height="1000" referenceOffsetX="0" referenceOffsetY="0"/>"""
    fun vehicle(children: String) = """<model version="7.0.0" name="m">
        <vehicle name="V" energyLevelCritical="30" energyLevelGood="90" energyLevelFullyRecharged="95"
            energyLevelSufficientlyRecharged="45" maxVelocity="1000" maxReverseVelocity="1000">$children</vehicle>
        </model>"""
    val adapter = """<property name="tcs:preferredAdapterClass" value="loopback"/>"""
    val color = """<property name="color" value="red"/>"""

    test("vehicle properties written before the bounding box are kept") {
        val read = read(vehicle("$adapter$color$box"))
        read.model.vehicles.single().properties shouldBe
            mapOf("tcs:preferredAdapterClass" to "loopback", "color" to "red")
        read.warnings shouldBe emptyList()
    }

    test("vehicle properties on both sides of the bounding box are all kept, with a warning") {
        val read = read(vehicle("$adapter$box$color"))
        read.model.vehicles.single().properties.keys shouldContainExactly setOf("tcs:preferredAdapterClass", "color")
        read.warnings.single().message shouldBe
            "<property> elements of <vehicle name=\"V\"> are not together (again at line 3); all of them are read"
    }

    test("an element the reader does not know is a warning naming it") {
        val read = read(vehicle("$box<wheel count=\"4\"/>"))
        read.warnings.map { it.element to it.message } shouldBe
            listOf("test.xml" to "ignored unknown 'wheel' in <vehicle>")
    }
})
