package org.ktcs.kernel.validation

import io.kotest.property.Arb
import io.kotest.property.arbitrary.arbitrary
import io.kotest.property.arbitrary.element
import io.kotest.property.arbitrary.enum
import io.kotest.property.arbitrary.int
import io.kotest.property.arbitrary.long
import io.kotest.property.arbitrary.map
import io.kotest.property.arbitrary.orNull
import io.kotest.property.arbitrary.shuffle
import io.kotest.property.arbitrary.subsequence
import org.ktcs.api.model.Block
import org.ktcs.api.model.BlockLayout
import org.ktcs.api.model.BoundingBox
import org.ktcs.api.model.EnergyLevelThresholdSet
import org.ktcs.api.model.Layer
import org.ktcs.api.model.LayerGroup
import org.ktcs.api.model.Link
import org.ktcs.api.model.Location
import org.ktcs.api.model.LocationLayout
import org.ktcs.api.model.LocationType
import org.ktcs.api.model.Path
import org.ktcs.api.model.PathLayout
import org.ktcs.api.model.PeripheralOperation
import org.ktcs.api.model.PlantModel
import org.ktcs.api.model.Point
import org.ktcs.api.model.PointLayout
import org.ktcs.api.model.PointType
import org.ktcs.api.model.Vehicle
import org.ktcs.api.model.VehicleLayout
import org.ktcs.api.model.VisualLayout

private val OPERATIONS = listOf("LOAD", "UNLOAD", "CHARGE", "DRILL", "NOP")

/**
 * Random plant models that break no error rule (warnings are allowed): every reference resolves by construction,
 * and each name carries a kind prefix and an index, so names never clash.
 */
fun Arb.Companion.validPlantModel(): Arb<PlantModel> = arbitrary {
    val layout = visualLayout().bind()
    val layers = layout.layers.map { it.id }
    val pointNames = List(Arb.int(1..20).bind()) { "Point-$it" }
    val types = List(Arb.int(0..3).bind()) { LocationType("Type-$it", someOf(OPERATIONS).bind().toSet()) }
    val locationNames = if (types.isEmpty()) emptyList() else List(Arb.int(0..6).bind()) { "Location-$it" }
    val paths = List(Arb.int(0..30).bind()) { path("Path-$it", pointNames, locationNames, layers).bind() }
    val resources = pointNames + paths.map { it.name } + locationNames
    PlantModel(
        name = "generated",
        points = pointNames.map { point(it, layers).bind() },
        paths = paths,
        vehicles = List(Arb.int(0..4).bind()) { vehicle("Vehicle-$it").bind() },
        locationTypes = types,
        locations = locationNames.map { location(it, types, pointNames, layers).bind() },
        blocks = List(Arb.int(0..3).bind()) { block("Block-$it", resources).bind() },
        visualLayout = layout,
    )
}

private fun visualLayout(): Arb<VisualLayout> = arbitrary {
    val groupIds = List(Arb.int(1..3).bind()) { it * 10 }
    val layers = List(Arb.int(1..4).bind()) { Layer(it, it, true, "Layer-$it", Arb.element(groupIds).bind()) }
    VisualLayout(layers = layers, layerGroups = groupIds.map { LayerGroup(it, "Group-$it", true) })
}

private fun point(name: String, layers: List<Int>): Arb<Point> = arbitrary {
    Point(name, type = Arb.enum<PointType>().bind(), layout = PointLayout(layerId = Arb.element(layers).bind()))
}

private fun path(name: String, points: List<String>, locations: List<String>, layers: List<Int>) = arbitrary {
    Path(
        name = name,
        sourcePoint = Arb.element(points).bind(),
        destinationPoint = Arb.element(points).bind(),
        length = Arb.long(1L..100_000L).bind(),
        maxVelocity = Arb.int(0..2_000).bind(),
        maxReverseVelocity = Arb.int(0..2_000).bind(),
        peripheralOperations = someOf(locations).bind().map { PeripheralOperation("OPEN", it) },
        layout = PathLayout(layerId = Arb.element(layers).bind()),
    )
}

private fun location(name: String, types: List<LocationType>, points: List<String>, layers: List<Int>) = arbitrary {
    val type = Arb.element(types).bind()
    val links = someOf(points).bind().map { Link(it, narrowed(type.allowedOperations).bind()) }
    Location(name, type.name, links = links, layout = LocationLayout(layerId = Arb.element(layers).bind()))
}

private fun narrowed(operations: Set<String>): Arb<Set<String>> =
    someOf(operations.toList()).map { it.toSet() }

private fun block(name: String, resources: List<String>): Arb<Block> = arbitrary {
    Block(name, members = someOf(resources).bind().toSet(), layout = BlockLayout(color().bind()))
}

private fun vehicle(name: String): Arb<Vehicle> = arbitrary {
    Vehicle(
        name = name,
        energyLevelThresholdSet = thresholds().bind(),
        maxVelocity = Arb.int(0..3_000).bind(),
        maxReverseVelocity = Arb.int(0..3_000).bind(),
        boundingBox = boundingBox().bind(),
        envelopeKey = Arb.element("small", "large").orNull().bind(),
        layout = VehicleLayout(color().bind()),
    )
}

private fun boundingBox(): Arb<BoundingBox> = arbitrary {
    BoundingBox(Arb.long(1L..5_000L).bind(), Arb.long(1L..5_000L).bind(), Arb.long(1L..5_000L).bind())
}

private fun thresholds(): Arb<EnergyLevelThresholdSet> = arbitrary {
    val critical = Arb.int(0..100).bind()
    val sufficientlyRecharged = Arb.int(0..100).bind()
    EnergyLevelThresholdSet(
        critical = critical,
        good = Arb.int(critical..100).bind(),
        sufficientlyRecharged = sufficientlyRecharged,
        fullyRecharged = Arb.int(sufficientlyRecharged..100).bind(),
    )
}

private fun color(): Arb<String> = Arb.int(0..0xFFFFFF).map { "#%06X".format(it) }

/** A random selection in random order; Kotest's subsequence alone only yields prefixes. */
private fun <T> someOf(items: List<T>): Arb<List<T>> = arbitrary { Arb.subsequence(Arb.shuffle(items).bind()).bind() }
