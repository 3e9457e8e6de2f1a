package org.ktcs.kernel.persistence

import io.kotest.property.Arb
import io.kotest.property.arbitrary.arbitrary
import io.kotest.property.arbitrary.boolean
import io.kotest.property.arbitrary.choice
import io.kotest.property.arbitrary.constant
import io.kotest.property.arbitrary.double
import io.kotest.property.arbitrary.enum
import io.kotest.property.arbitrary.int
import io.kotest.property.arbitrary.list
import io.kotest.property.arbitrary.long
import io.kotest.property.arbitrary.map
import io.kotest.property.arbitrary.of
import io.kotest.property.arbitrary.orNull
import io.kotest.property.arbitrary.set
import org.ktcs.api.model.Block
import org.ktcs.api.model.BlockLayout
import org.ktcs.api.model.BlockType
import org.ktcs.api.model.BoundingBox
import org.ktcs.api.model.ConnectionType
import org.ktcs.api.model.Couple
import org.ktcs.api.model.EnergyLevelThresholdSet
import org.ktcs.api.model.Envelope
import org.ktcs.api.model.ExecutionTrigger
import org.ktcs.api.model.Layer
import org.ktcs.api.model.LayerGroup
import org.ktcs.api.model.Link
import org.ktcs.api.model.Location
import org.ktcs.api.model.LocationLayout
import org.ktcs.api.model.LocationRepresentation
import org.ktcs.api.model.LocationType
import org.ktcs.api.model.LocationTypeLayout
import org.ktcs.api.model.Path
import org.ktcs.api.model.PathLayout
import org.ktcs.api.model.PeripheralOperation
import org.ktcs.api.model.PlantModel
import org.ktcs.api.model.Point
import org.ktcs.api.model.PointLayout
import org.ktcs.api.model.PointType
import org.ktcs.api.model.Pose
import org.ktcs.api.model.Position
import org.ktcs.api.model.Vehicle
import org.ktcs.api.model.VehicleLayout
import org.ktcs.api.model.VisualLayout

/** Generators for plant models holding anything a 7.0.0 file can express; vehicles keep runtime defaults. */
object PlantModelArbs {
    /** XML-special characters, whitespace XML would normalise, and non-ASCII up to a surrogate pair. */
    private val alphabet = listOf("a", "Z", "7", "-", " ", "&", "<", ">", "\"", "'", "\t", "\n", "\r", "é", "中", "😀")

    val text: Arb<String> = Arb.list(Arb.of(alphabet), 0..8).map { it.joinToString("") }

    private val properties = Arb.map(text, text, maxSize = 3)
    private val couple = arbitrary { Couple(Arb.long().bind(), Arb.long().bind()) }
    private val couples = Arb.list(couple, 0..3)
    private val envelopes = Arb.map(text, Arb.list(couple, 1..4).map(::Envelope), maxSize = 2)
    private val color = Arb.list(Arb.of("0123456789ABCDEF".map { "$it" }), 6..6).map { "#" + it.joinToString("") }
    private val unsignedInt = Arb.int(0..Int.MAX_VALUE)
    private val orientation = Arb.choice(Arb.constant(Double.NaN), Arb.double(-360.0, 360.0))

    private val boundingBox = arbitrary {
        BoundingBox(Arb.long().bind(), Arb.long().bind(), Arb.long().bind(), couple.bind())
    }

    private val position = arbitrary { Position(Arb.long().bind(), Arb.long().bind(), Arb.long().bind()) }

    private val point = arbitrary {
        Point(
            name = text.bind(),
            pose = Pose(position.bind(), orientation.bind()),
            type = Arb.enum<PointType>().bind(),
            maxVehicleBoundingBox = boundingBox.bind(),
            vehicleEnvelopes = envelopes.bind(),
            layout = PointLayout(couple.bind(), Arb.int().bind()),
            properties = properties.bind(),
        )
    }

    private fun path(pointNames: Arb<String>) = arbitrary {
        Path(
            name = text.bind(),
            sourcePoint = pointNames.bind(),
            destinationPoint = pointNames.bind(),
            length = Arb.long(0L..4_294_967_295L).bind(),
            maxVelocity = unsignedInt.bind(),
            maxReverseVelocity = unsignedInt.bind(),
            peripheralOperations = Arb.list(peripheralOperation, 0..3).bind(),
            locked = Arb.boolean().bind(),
            vehicleEnvelopes = envelopes.bind(),
            layout = PathLayout(Arb.enum<ConnectionType>().bind(), couples.bind(), Arb.int().bind()),
            properties = properties.bind(),
        )
    }

    private val peripheralOperation = arbitrary {
        PeripheralOperation(
            text.bind(),
            text.bind(),
            Arb.enum<ExecutionTrigger>().bind(),
            Arb.boolean().bind(),
        )
    }

    private val vehicle = arbitrary {
        val levels = Arb.int(0..100)
        Vehicle(
            name = text.bind(),
            energyLevelThresholdSet = EnergyLevelThresholdSet(
                levels.bind(),
                levels.bind(),
                levels.bind(),
                levels.bind(),
            ),
            maxVelocity = unsignedInt.bind(),
            maxReverseVelocity = unsignedInt.bind(),
            boundingBox = boundingBox.bind(),
            envelopeKey = text.orNull().bind(),
            layout = VehicleLayout(color.bind()),
            properties = properties.bind(),
        )
    }

    private val representation = Arb.enum<LocationRepresentation>()

    private val locationType = arbitrary {
        LocationType(
            name = text.bind(),
            allowedOperations = Arb.set(text, 0..3).bind(),
            allowedPeripheralOperations = Arb.set(text, 0..3).bind(),
            layout = LocationTypeLayout(representation.bind()),
            properties = properties.bind(),
        )
    }

    private fun location(pointNames: Arb<String>) = arbitrary {
        Location(
            name = text.bind(),
            type = text.bind(),
            position = position.bind(),
            links = Arb.list(arbitrary { Link(pointNames.bind(), Arb.set(text, 0..2).bind()) }, 0..2).bind(),
            locked = Arb.boolean().bind(),
            layout = LocationLayout(couple.bind(), representation.bind(), Arb.int().bind()),
            properties = properties.bind(),
        )
    }

    private val block = arbitrary {
        Block(
            name = text.bind(),
            type = Arb.enum<BlockType>().bind(),
            members = Arb.set(text, 0..3).bind(),
            layout = BlockLayout(color.bind()),
            properties = properties.bind(),
        )
    }

    private val visualLayout = arbitrary {
        VisualLayout(
            name = text.bind(),
            scaleX = Arb.double(0.001, 1e6).bind(),
            scaleY = Arb.double(0.001, 1e6).bind(),
            layers = Arb.list(layer, 1..3).bind(),
            layerGroups = Arb.list(arbitrary { LayerGroup(Arb.int().bind(), text.bind(), Arb.boolean().bind()) }, 1..2)
                .bind(),
            properties = properties.bind(),
        )
    }

    private val layer = arbitrary {
        Layer(Arb.int().bind(), Arb.int().bind(), Arb.boolean().bind(), text.bind(), Arb.int().bind())
    }

    /** Paths and links mostly connect generated points, sometimes name points that do not exist. */
    val plantModel: Arb<PlantModel> = arbitrary {
        val points = Arb.list(point, 0..6).bind()
        val pointNames = if (points.isEmpty()) text else Arb.choice(Arb.of(points.map { it.name }), text)
        PlantModel(
            name = text.bind(),
            points = points,
            paths = Arb.list(path(pointNames), 0..6).bind(),
            vehicles = Arb.list(vehicle, 0..3).bind(),
            locationTypes = Arb.list(locationType, 0..3).bind(),
            locations = Arb.list(location(pointNames), 0..3).bind(),
            blocks = Arb.list(block, 0..3).bind(),
            visualLayout = visualLayout.bind(),
            properties = properties.bind(),
        )
    }
}
