package org.ktcs.kernel.routing

import io.kotest.property.Arb
import io.kotest.property.arbitrary.arbitrary
import io.kotest.property.arbitrary.boolean
import io.kotest.property.arbitrary.element
import io.kotest.property.arbitrary.int
import io.kotest.property.arbitrary.list
import io.kotest.property.arbitrary.long
import io.kotest.property.arbitrary.subsequence
import org.ktcs.api.model.Link
import org.ktcs.api.model.Path
import org.ktcs.api.model.PlantModel
import org.ktcs.api.model.Point
import org.ktcs.api.model.Vehicle
import org.ktcs.api.order.VehicleOrientation
import kotlin.math.roundToLong

/** A random grid-like plant, a vehicle, cost functions and the points a route should join. */
data class GridCase(
    val model: PlantModel,
    val vehicle: Vehicle,
    val evaluators: List<EdgeEvaluator>,
    val source: String,
    val destination: String,
)

/** One drivable direction of a path, as the reference computation sees it. */
data class Direction(val path: Path, val from: String, val to: String, val orientation: VehicleOrientation)

private val velocities = Arb.element(0, 0, 100, 500, 1000, 2000)

private val evaluatorChoices: Arb<List<EdgeEvaluator>> = arbitrary {
    val chosen = Arb.subsequence(listOf(EdgeEvaluator.DISTANCE, EdgeEvaluator.HOPS, EdgeEvaluator.TRAVELTIME)).bind()
    chosen.ifEmpty { listOf(EdgeEvaluator.DISTANCE) }
}

/** A path between two neighbours in a random direction, with random length and velocities, locked one time in ten. */
private fun gridPath(first: String, second: String): Arb<Path> = arbitrary {
    val (source, target) = if (Arb.boolean().bind()) first to second else second to first
    path(source, target, Arb.long(1L..1000L).bind(), velocities.bind(), velocities.bind(), Arb.int(0..9).bind() == 0)
}

/** Grids of up to 4 by 4 points joined to most right and lower neighbours, with three locations linked at random. */
val gridCases: Arb<GridCase> = arbitrary {
    val width = Arb.int(1..4).bind()
    val height = Arb.int(1..4).bind()
    val names = (0 until width).flatMap { x -> (0 until height).map { y -> "$x/$y" } }
    val neighbours = names.flatMap { name -> neighboursOf(name, width, height).map { name to it } }
    val paths = neighbours.filter { Arb.int(0..4).bind() > 0 }.map { (first, second) -> gridPath(first, second).bind() }
    val stations = (0..2).map { index ->
        station("L$index", *Arb.list(Arb.element(names), 1..3).bind().map(::Link).toTypedArray())
    }
    GridCase(
        model = plant(*paths.toTypedArray(), extraPoints = names.map(::Point), locations = stations),
        vehicle = vehicle(maxVelocity = Arb.int(1..2000).bind(), maxReverseVelocity = velocities.bind()),
        evaluators = evaluatorChoices.bind(),
        source = Arb.element(names).bind(),
        destination = Arb.element(names).bind(),
    )
}

private fun neighboursOf(name: String, width: Int, height: Int): List<String> {
    val (x, y) = name.split('/').map(String::toInt)
    return listOfNotNull("${x + 1}/$y".takeIf { x + 1 < width }, "$x/${y + 1}".takeIf { y + 1 < height })
}

/** Every direction a vehicle may drive, computed directly from the paths. */
fun GridCase.directions(): List<Direction> = model.paths.filterNot { it.locked }.flatMap { path ->
    listOfNotNull(
        Direction(path, path.sourcePoint, path.destinationPoint, VehicleOrientation.FORWARD).takeIf {
            path.maxVelocity !=
                0
        },
        Direction(path, path.destinationPoint, path.sourcePoint, VehicleOrientation.BACKWARD)
            .takeIf { path.maxReverseVelocity != 0 },
    )
}

/** The evaluators' summed cost of [direction], or `null` where one forbids it, computed independently of the router. */
fun GridCase.costOf(direction: Direction): Long? = evaluators.fold(0L as Long?) { total, evaluator ->
    val backward = direction.orientation == VehicleOrientation.BACKWARD
    val cost = when (evaluator) {
        EdgeEvaluator.DISTANCE -> direction.path.length

        EdgeEvaluator.HOPS -> 1L

        else -> {
            val pathVelocity = if (backward) direction.path.maxReverseVelocity else direction.path.maxVelocity
            val velocity = minOf(pathVelocity, if (backward) vehicle.maxReverseVelocity else vehicle.maxVelocity)
            if (velocity <= 0) null else (direction.path.length * 1000.0 / velocity).roundToLong()
        }
    }
    if (total == null || cost == null) null else total + cost
}

/** The cheapest cost from [from] to every point it reaches: Bellman-Ford over [directions], no JGraphT. */
fun GridCase.cheapestCostsFrom(from: String): Map<String, Long> {
    val edges = directions().mapNotNull { direction ->
        costOf(direction)?.let { Triple(direction.from, direction.to, it) }
    }
    val best = HashMap(mapOf(from to 0L))
    repeat(model.points.size) {
        for ((source, target, cost) in edges) {
            val viaSource = best[source]?.plus(cost) ?: continue
            if (viaSource < (best[target] ?: Long.MAX_VALUE)) best[target] = viaSource
        }
    }
    return best
}
