package org.ktcs.kernel.web.v1.plantmodel

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.doubles.shouldBeNaN
import io.kotest.matchers.shouldBe
import org.ktcs.api.model.BlockType
import org.ktcs.api.model.BoundingBox
import org.ktcs.api.model.ConnectionType
import org.ktcs.api.model.Couple
import org.ktcs.api.model.EnergyLevelThresholdSet
import org.ktcs.api.model.Envelope
import org.ktcs.api.model.ExecutionTrigger
import org.ktcs.api.model.LocationRepresentation
import org.ktcs.api.model.PeripheralOperation
import org.ktcs.api.model.PlantModel
import org.ktcs.api.model.PointType
import org.ktcs.api.model.Position
import org.ktcs.kernel.web.v1.GoldenJson
import org.ktcs.kernel.web.v1.GoldenJson.shouldEqualJsonElement
import org.ktcs.kernel.web.v1.V1Json

class PlantModelDtoTest : FunSpec({
    val sample = "binding/PlantModelTOTest.jsonSample.approved.txt"

    fun decodeSample(): PlantModel = V1Json.decodeRequest<PlantModelDto>(GoldenJson.text(sample)).toDomain()

    test("reads the points of openTCS's plant model sample") {
        val points = decodeSample().points

        points.map { it.name } shouldBe listOf("some-point", "some-point2", "some-point3")
        points[0].pose.position shouldBe Position(25000, -15000, 0)
        points[0].pose.orientationAngle shouldBe 73.3
        points[1].pose.orientationAngle.shouldBeNaN()
        points[0].type shouldBe PointType.PARK_POSITION
        points[0].layout.labelOffset shouldBe Couple(-10, -20)
        points[0].vehicleEnvelopes.getValue("envelopeType-01").vertices.first() shouldBe Couple(25500, -15500)
        points[0].maxVehicleBoundingBox shouldBe BoundingBox(1500, 2000, 3000, Couple(10, 20))
        points[0].properties shouldBe mapOf("point-prop" to "point-value")
    }

    test("reads the paths of openTCS's plant model sample") {
        val path = decodeSample().paths.first()

        path.sourcePoint shouldBe "some-point"
        path.destinationPoint shouldBe "some-point2"
        path.length shouldBe 3
        path.maxVelocity shouldBe 13
        path.maxReverseVelocity shouldBe 3
        path.locked shouldBe true
        path.peripheralOperations shouldBe
            listOf(PeripheralOperation("some-op", "some-location", ExecutionTrigger.AFTER_ALLOCATION, true))
        path.layout.connectionType shouldBe ConnectionType.SLANTED
        path.layout.controlPoints.size shouldBe 3
        path.vehicleEnvelopes.keys shouldBe setOf("envelopeType-01")
        path.properties shouldBe mapOf("path-prop" to "path-value")
    }

    test("reads locations, blocks, vehicles and the visual layout of openTCS's sample") {
        val model = decodeSample()

        model.name shouldBe "some-name"
        model.locationTypes.single().allowedOperations shouldBe
            setOf("some-operation", "another-operation", "operation3")
        model.locationTypes.single().layout.locationRepresentation shouldBe LocationRepresentation.WORKING_GENERIC
        model.locations.single().type shouldBe "some-locationType"
        model.locations.single().locked shouldBe true
        model.locations.single().layout.locationRepresentation shouldBe LocationRepresentation.LOAD_TRANSFER_GENERIC
        model.blocks.single().type shouldBe BlockType.SAME_DIRECTION_ONLY
        model.blocks.single().members shouldBe setOf("some-point2")
        model.vehicles.single().boundingBox shouldBe BoundingBox(150, 200, 300, Couple(10, 20))
        model.vehicles.single().energyLevelThresholdSet shouldBe EnergyLevelThresholdSet(10, 30, 60, 90)
        model.vehicles.single().maxReverseVelocity shouldBe 733
        model.vehicles.single().envelopeKey shouldBe "envelopeType-01"
        model.vehicles.single().layout.routeColor shouldBe "#123456"
        model.visualLayout.scaleX shouldBe 65.0
        model.visualLayout.layers.single().name shouldBe "layer0"
        model.properties shouldBe mapOf("plantModel-prop" to "value")
    }

    test("writes the model read from openTCS's sample back exactly as the sample") {
        V1Json.json.encodeToString(PlantModelDto.serializer(), decodeSample().toDto()) shouldEqualJsonElement
            GoldenJson.element(sample)
    }

    test("an envelope in the domain is written with its key") {
        val dto = mapOf("e" to Envelope(listOf(Couple(1, 2)))).toEnvelopeDtos()

        dto.single().key shouldBe "e"
    }
})
