package org.ktcs.kernel.simulation

import org.ktcs.api.model.Block
import org.ktcs.api.model.BlockType
import org.ktcs.api.model.Link
import org.ktcs.api.model.Location
import org.ktcs.api.model.Path
import org.ktcs.api.model.PlantModel
import org.ktcs.api.model.Point
import org.ktcs.api.model.PointType
import org.ktcs.api.model.Pose
import org.ktcs.api.model.Position
import kotlin.random.Random

/** How a lane between two neighbouring grid points may be driven. */
enum class Lane { FORWARD, BACKWARD, TWO_WAY, NONE }

/**
 * A small random plant for property tests: a [width] × [height] grid of points 2 m apart whose lanes are one-way
 * (either direction), two-way or missing ([lanes], row lanes first, then column lanes), with dead-end stubs (two-way,
 * one stop each) for [stations] transfer stations and [vehicles] park bays, and optionally a SINGLE_VEHICLE_ONLY
 * block over one unit square and a SAME_DIRECTION_ONLY block over one two-way lane.
 */
data class RandomPlant(
    val width: Int,
    val height: Int,
    val lanes: List<Lane>,
    val stations: Int,
    val vehicles: Int,
    val blocks: Boolean,
    val seed: Long,
) {
    private val points = ArrayList<Point>()
    private val paths = ArrayList<Path>()

    fun build(): PlantModel {
        points.clear()
        paths.clear()
        val random = Random(seed)
        for (y in 0 until height) for (x in 0 until width) points += point(grid(x, y), x, y)
        neighbours().zip(lanes).forEach { (pair, lane) -> lane(pair.first, pair.second, lane) }
        val gridPoints = points.map { it.name }.shuffled(random)
        val locations = (0 until stations).map { n ->
            val stub = stub("Stub-%02d".format(n + 1), gridPoints[n % gridPoints.size], PointType.HALT_POSITION)
            Location(
                "Station-%02d".format(n + 1),
                TrafficGrid.TRANSFER_TYPE,
                stub.pose.position,
                listOf(Link(stub.name)),
            )
        }
        val fleet = (0 until vehicles).map { n ->
            val bay =
                stub("Park-%02d".format(n + 1), gridPoints[(stations + n) % gridPoints.size], PointType.PARK_POSITION)
            TrafficGrid.benchmarkVehicle(n + 1, bay.name)
        }
        return PlantModel(
            name = toString(),
            points = points.toList(),
            paths = paths.toList(),
            locationTypes = listOf(TrafficGrid.transferStationType()),
            locations = locations,
            vehicles = fleet,
            blocks = if (blocks) randomBlocks(random) else emptyList(),
        )
    }

    /** Whether every grid point reaches every other over the lanes (stubs are two-way and always reach back). */
    fun isStronglyConnected(): Boolean {
        val forward = HashMap<String, MutableSet<String>>()
        val backward = HashMap<String, MutableSet<String>>()
        for ((pair, lane) in neighbours().zip(lanes)) {
            val (a, b) = pair
            if (lane == Lane.FORWARD || lane == Lane.TWO_WAY) forward.getOrPut(a, ::HashSet) += b
            if (lane == Lane.BACKWARD || lane == Lane.TWO_WAY) forward.getOrPut(b, ::HashSet) += a
        }
        forward.forEach { (from, tos) -> tos.forEach { backward.getOrPut(it, ::HashSet) += from } }
        val start = grid(0, 0)
        return reached(start, forward).size == width * height && reached(start, backward).size == width * height
    }

    private fun reached(start: String, edges: Map<String, Set<String>>): Set<String> {
        val seen = hashSetOf(start)
        val queue = ArrayDeque(listOf(start))
        while (queue.isNotEmpty()) edges[queue.removeFirst()].orEmpty().forEach { if (seen.add(it)) queue += it }
        return seen
    }

    private fun neighbours(): List<Pair<String, String>> =
        (0 until height).flatMap { y -> (0 until width - 1).map { x -> grid(x, y) to grid(x + 1, y) } } +
            (0 until width).flatMap { x -> (0 until height - 1).map { y -> grid(x, y) to grid(x, y + 1) } }

    private fun randomBlocks(random: Random): List<Block> {
        val x = random.nextInt(width - 1)
        val y = random.nextInt(height - 1)
        val corners = setOf(grid(x, y), grid(x + 1, y), grid(x + 1, y + 1), grid(x, y + 1))
        val square = paths.filter { it.sourcePoint in corners && it.destinationPoint in corners }.map { it.name }
        val twoWay = paths.filter {
            it.maxReverseVelocity > 0 && it.sourcePoint.startsWith("G") &&
                it.destinationPoint.startsWith("G")
        }
        return listOfNotNull(
            Block("Square", BlockType.SINGLE_VEHICLE_ONLY, corners + square),
            twoWay.randomOrNull(random)?.let {
                Block("Corridor", BlockType.SAME_DIRECTION_ONLY, setOf(it.name, it.sourcePoint, it.destinationPoint))
            }?.takeIf { corridor -> corridor.members.none { it in corners } },
        )
    }

    private fun stub(name: String, at: String, type: PointType): Point {
        val base = points.first { it.name == at }.pose.position
        val offset = STUB_LENGTH * (1 + points.count { it.name.startsWith("Stub") || it.name.startsWith("Park") } % 3)
        val stub = Point(name, Pose(Position(base.x + offset / 3, base.y + offset, 0)), type)
        points += stub
        paths += Path("$at --- $name", at, name, STUB_LENGTH, TrafficGrid.SPEED, TrafficGrid.SPEED)
        return stub
    }

    private fun lane(from: String, to: String, lane: Lane) {
        when (lane) {
            Lane.FORWARD -> paths += Path("$from --- $to", from, to, SPACING, TrafficGrid.SPEED)
            Lane.BACKWARD -> paths += Path("$to --- $from", to, from, SPACING, TrafficGrid.SPEED)
            Lane.TWO_WAY -> paths += Path("$from --- $to", from, to, SPACING, TrafficGrid.SPEED, TrafficGrid.SPEED)
            Lane.NONE -> Unit
        }
    }

    private fun grid(x: Int, y: Int) = "G-$x-$y"

    private fun point(name: String, x: Int, y: Int) = Point(name, Pose(Position(x * SPACING, y * SPACING, 0)))

    companion object {
        const val SPACING = 2_000L
        const val STUB_LENGTH = 1_500L

        /** How many lanes a [width] × [height] grid has. */
        fun laneCount(width: Int, height: Int) = height * (width - 1) + width * (height - 1)
    }
}
