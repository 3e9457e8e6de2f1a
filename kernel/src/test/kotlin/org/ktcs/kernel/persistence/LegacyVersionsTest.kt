package org.ktcs.kernel.persistence

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import org.ktcs.api.model.Block
import org.ktcs.api.model.BlockLayout
import org.ktcs.api.model.BlockType
import org.ktcs.api.model.BoundingBox
import org.ktcs.api.model.ConnectionType
import org.ktcs.api.model.Couple
import org.ktcs.api.model.EnergyLevelThresholdSet
import org.ktcs.api.model.Link
import org.ktcs.api.model.Location
import org.ktcs.api.model.LocationLayout
import org.ktcs.api.model.LocationRepresentation
import org.ktcs.api.model.LocationType
import org.ktcs.api.model.LocationTypeLayout
import org.ktcs.api.model.Path
import org.ktcs.api.model.PathLayout
import org.ktcs.api.model.PlantModel
import org.ktcs.api.model.Point
import org.ktcs.api.model.PointLayout
import org.ktcs.api.model.PointType
import org.ktcs.api.model.Pose
import org.ktcs.api.model.Position
import org.ktcs.api.model.Vehicle
import org.ktcs.api.model.VehicleLayout
import org.ktcs.api.model.VisualLayout
import org.ktcs.kernel.persistence.PersistenceFixtures.HANDWRITTEN_V002

/** A hand-written 4.x (0.0.2) file, converted as openTCS converts it; see handwritten-0.0.2.xml. */
class LegacyVersionsTest : FunSpec({
    test("the hand-written file is a valid 0.0.2 model") {
        PersistenceFixtures.validate(PersistenceFixtures.text(HANDWRITTEN_V002), PersistenceFixtures.schema("0.0.2"))
    }

    test("a 0.0.2 file becomes the model 7.0.0 would hold, without its 4.x-only parts") {
        PlantModelFiles.read(PersistenceFixtures.path(HANDWRITTEN_V002)) shouldBe expectedHandwrittenModel
    }
})

private val expectedHandwrittenModel = PlantModel(
    name = "Handwritten-0.0.2",
    points = listOf(
        Point(
            "Point-A",
            Pose(Position(1000, 2000, 5), 90.0),
            layout = PointLayout(Couple(-15, 25)),
            properties = mapOf("pt-key" to "pt-value"),
        ),
        Point("Point-B", Pose(Position(6000, 2000, 0)), PointType.HALT_POSITION, layout = PointLayout(Couple(0, 0))),
        Point("Point-C", Pose(Position(6000, -3000, 0)), PointType.PARK_POSITION, layout = PointLayout(Couple(0, 0))),
    ),
    paths = listOf(
        Path(
            "A --- B",
            "Point-A",
            "Point-B",
            length = 5000,
            maxVelocity = 1000,
            maxReverseVelocity = 500,
            layout = PathLayout(ConnectionType.POLYPATH, listOf(Couple(10, -20), Couple(30, -40))),
            properties = mapOf("path-key" to "path-value"),
        ),
        Path("B --- C", "Point-B", "Point-C", length = 1, maxVelocity = 800, maxReverseVelocity = 0, locked = true),
    ),
    vehicles = listOf(
        Vehicle(
            "Vehicle-1",
            EnergyLevelThresholdSet(critical = 20, good = 85, sufficientlyRecharged = 30, fullyRecharged = 90),
            maxVelocity = 1500,
            boundingBox = BoundingBox(length = 1200, width = 1000, height = 1000),
            layout = VehicleLayout("#33CC00"),
            properties = mapOf("loopback:loadOperation" to "Load cargo"),
        ),
        Vehicle("Vehicle-2", layout = VehicleLayout("#FF0000")),
    ),
    locationTypes = listOf(
        LocationType(
            "Station",
            allowedOperations = setOf("Load cargo", "Unload cargo"),
            layout = LocationTypeLayout(LocationRepresentation.LOAD_TRANSFER_GENERIC),
            properties = mapOf("tcs:defaultLocationTypeSymbol" to "LOAD_TRANSFER_GENERIC"),
        ),
    ),
    locations = listOf(
        Location(
            "Station-1",
            "Station",
            Position(1000, 5000, 0),
            links = listOf(Link("Point-A", setOf("Load cargo"))),
            locked = true,
            layout = LocationLayout(Couple(5, 6), LocationRepresentation.WORKING_GENERIC),
            properties = mapOf("tcs:defaultLocationSymbol" to "WORKING_GENERIC"),
        ),
        Location(
            "Station-2",
            "Station",
            Position(0, 0, 0),
            links = listOf(Link("Point-C")),
            layout = LocationLayout(Couple(0, 0)),
        ),
    ),
    blocks = listOf(
        Block("Block-1", BlockType.SINGLE_VEHICLE_ONLY, setOf("Point-B", "A --- B"), BlockLayout("#0000FF")),
        Block("Block-2", BlockType.SAME_DIRECTION_ONLY, layout = BlockLayout("#FF0000")),
    ),
    visualLayout = VisualLayout("VLayout-1", 25.0, 40.0, properties = mapOf("vl-key" to "vl-value")),
    properties = mapOf("model-key" to "model-value"),
)
