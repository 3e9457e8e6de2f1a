package org.ktcs.kernel.persistence

import io.kotest.core.spec.style.FunSpec
import io.kotest.engine.spec.tempdir
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldStartWith
import org.ktcs.api.model.Path
import org.ktcs.api.model.PlantModel
import org.ktcs.api.model.Point
import org.ktcs.api.model.Pose
import org.ktcs.api.model.Position
import java.io.File

class PlantModelFilesTest : FunSpec({
    fun read(xml: String) = PlantModelFiles.read(xml.byteInputStream(), "test.xml")

    val box = """<maxVehicleBoundingBox length="1" width="1" height="1" referenceOffsetX="0" referenceOffsetY="0"/>"""

    test("write stores exactly writeToString, and read gives the model back") {
        val model = PlantModel("Plant", points = listOf(Point("P")), paths = listOf(Path("P --- P", "P", "P")))
        val file = File(tempdir(), "plant.xml").toPath()
        PlantModelFiles.write(model, file)
        PlantModelFiles.write(model, file)
        file.toFile().readText() shouldBe PlantModelFiles.writeToString(model)
        PlantModelFiles.read(file) shouldBe model
        file.parent.toFile().list()!!.toList() shouldBe listOf("plant.xml")
    }

    test("the written file starts with openTCS's declaration and root") {
        PlantModelFiles.writeToString(PlantModel("M")) shouldStartWith
            "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"yes\"?>\n<model version=\"7.0.0\" name=\"M\">\n"
    }

    test("outgoing paths in the file are ignored: they are derived from the paths") {
        val xml = """<model version="7.0.0" name="m"><point name="P" positionX="0" positionY="0" positionZ="0"
            type="HALT_POSITION">$box<outgoingPath name="no such path"/></point></model>"""
        val model = read(xml)
        model.points.single().name shouldBe "P"
        PlantModelFiles.writeToString(model).contains("outgoingPath") shouldBe false
    }

    test("the reader leaves the model's meaning to the validator") {
        val xml = """<model version="7.0.0" name="m">
            <point name="Twin" positionX="0" positionY="0" positionZ="0" type="HALT_POSITION">$box</point>
            <point name="Twin" positionX="1" positionY="1" positionZ="0" type="PARK_POSITION">$box</point>
            <path name="Twin" sourcePoint="Nowhere" destinationPoint="Twin" length="-5" maxVelocity="1"
                maxReverseVelocity="0" locked="false"/>
            <vehicle name="V" energyLevelCritical="95" energyLevelGood="10" energyLevelFullyRecharged="5"
                energyLevelSufficientlyRecharged="99" maxVelocity="1" maxReverseVelocity="1">
                <boundingBox length="-1" width="1" height="1" referenceOffsetX="0" referenceOffsetY="0"/></vehicle>
            </model>"""
        val model = read(xml)
        model.points.map { it.name } shouldBe listOf("Twin", "Twin")
        model.paths.single().length shouldBe -5
        model.vehicles.single().energyLevelThresholdSet.critical shouldBe 95
    }

    test("xsd:float spellings of the orientation are read, and written back as the schema spells them") {
        fun angle(value: String) = read(
            """<model version="7.0.0" name="m"><point name="P" positionX="0" positionY="0" positionZ="0"
                vehicleOrientationAngle="$value" type="HALT_POSITION">$box</point></model>""",
        ).points.single().pose.orientationAngle
        angle("INF") shouldBe Double.POSITIVE_INFINITY
        angle("-1.5E2") shouldBe -150.0
        angle("NaN").isNaN() shouldBe true
        val infinite = PlantModel("m", points = listOf(Point("P", Pose(Position(0, 0), Double.NEGATIVE_INFINITY))))
        PlantModelFiles.writeToString(infinite).contains("vehicleOrientationAngle=\"-INF\"") shouldBe true
    }

    test("an orientation left out means unknown") {
        val xml = """<model version="7.0.0" name="m"><point name="P" positionX="0" positionY="0" positionZ="0"
            type="HALT_POSITION">$box</point></model>"""
        read(xml).points.single().pose.orientationAngle.isNaN() shouldBe true
    }
})
