package org.ktcs.kernel.simulation

import org.ktcs.api.model.BoundingBox
import org.ktcs.api.model.Link
import org.ktcs.api.model.Location
import org.ktcs.api.model.LocationRepresentation
import org.ktcs.api.model.LocationType
import org.ktcs.api.model.LocationTypeLayout
import org.ktcs.api.model.Path
import org.ktcs.api.model.PlantModel
import org.ktcs.api.model.Point
import org.ktcs.api.model.PointType
import org.ktcs.api.model.Pose
import org.ktcs.api.model.Position
import org.ktcs.api.model.Vehicle
import kotlin.math.hypot
import kotlin.math.roundToLong

/**
 * The traffic benchmark plant (issue #11): [width] × [height] halt points 2 m apart joined by one-way lanes whose
 * direction alternates row by row and column by column (half of all unit squares are directed 4-cycles); the border
 * lanes form one counter-clockwise ring. A transfer station (Load cargo / Unload cargo) stands beside every 4th
 * border point, linked to it; each of the [vehicles] vehicles (1 m long, 1 m/s) has a park bay of its own 1.5 m
 * outside the border, a detour off the ring, and starts there.
 */
class TrafficGrid(private val width: Int, private val height: Int, private val vehicles: Int) {
    init {
        require(width >= 3 && height >= 3) { "a traffic grid needs at least 3x3 points, got ${width}x$height" }
        require(vehicles >= 1) { "a traffic grid needs at least 1 vehicle, got $vehicles" }
        require(vehicles <= ring().size) {
            "a ${width}x$height traffic grid has room for ${ring().size} park bays, not $vehicles vehicles"
        }
    }

    fun build(): PlantModel {
        val points = ArrayList<Point>()
        val paths = ArrayList<Path>()
        for (y in 0 until height) for (x in 0 until width) points += Point(point(x, y), Pose(at(x, y)))
        for (y in 0 until height) for (x in 0 until width - 1) paths += lane(x, y, x + 1, y, eastbound(y))
        for (x in 0 until width) for (y in 0 until height - 1) paths += lane(x, y, x, y + 1, northbound(x))
        val ring = ring()
        val locations = ring.indices.filter { it % STATION_EVERY == 0 }.map { i ->
            val (x, y) = ring[i]
            Location(
                "Station-%03d".format(i / STATION_EVERY + 1),
                TRANSFER_TYPE,
                outside(x, y, STATION_OFFSET),
                listOf(Link(point(x, y))),
            )
        }
        val fleet = (0 until vehicles).map { n ->
            val segment = n * ring.size / vehicles
            val (from, to) = ring[segment] to ring[(segment + 1) % ring.size]
            val bay = "Park-%03d".format(n + 1)
            points += Point(bay, Pose(bayPosition(from, to)), PointType.PARK_POSITION)
            paths += detour(point(from.first, from.second), bay, at(from.first, from.second), bayPosition(from, to))
            paths += detour(bay, point(to.first, to.second), bayPosition(from, to), at(to.first, to.second))
            benchmarkVehicle(n + 1, bay)
        }
        return PlantModel(
            name = "Traffic grid ${width}x$height, $vehicles vehicles",
            points = points,
            paths = paths,
            locationTypes = listOf(transferStationType()),
            locations = locations,
            vehicles = fleet,
        )
    }

    /** The border points in driving order (counter-clockwise), starting at the bottom-left corner. */
    private fun ring(): List<Pair<Int, Int>> =
        (0 until width - 1).map { it to 0 } +
            (0 until height - 1).map { width - 1 to it } +
            (width - 1 downTo 1).map { it to height - 1 } +
            (height - 1 downTo 1).map { 0 to it }

    // Counter-clockwise ring: bottom row east, right column north, top row west, left column south; inside, rows and
    // columns alternate.
    private fun eastbound(y: Int) = when (y) {
        0 -> true
        height - 1 -> false
        else -> y % 2 == 0
    }

    private fun northbound(x: Int) = when (x) {
        0 -> false
        width - 1 -> true
        else -> x % 2 == 1
    }

    private fun lane(x1: Int, y1: Int, x2: Int, y2: Int, forward: Boolean): Path {
        val (from, to) = if (forward) point(x1, y1) to point(x2, y2) else point(x2, y2) to point(x1, y1)
        return Path("$from --- $to", from, to, SPACING, maxVelocity = SPEED)
    }

    private fun detour(from: String, to: String, a: Position, b: Position): Path =
        Path(
            "$from --- $to",
            from,
            to,
            hypot((b.x - a.x).toDouble(), (b.y - a.y).toDouble()).roundToLong(),
            maxVelocity = SPEED,
        )

    private fun point(x: Int, y: Int) = "P-%02d-%02d".format(x, y)

    private fun at(x: Int, y: Int) = Position(x * SPACING, y * SPACING, 0)

    /** [distance] outside the border next to point ([x], [y]) (corners: diagonally). */
    private fun outside(x: Int, y: Int, distance: Long): Position {
        val dx = when (x) {
            0 -> -1
            width - 1 -> 1
            else -> 0
        }
        val dy = when (y) {
            0 -> -1
            height - 1 -> 1
            else -> 0
        }
        return Position(x * SPACING + dx * distance, y * SPACING + dy * distance, 0)
    }

    private fun bayPosition(from: Pair<Int, Int>, to: Pair<Int, Int>): Position {
        val a = outside(from.first, from.second, PARK_OFFSET)
        val b = outside(to.first, to.second, PARK_OFFSET)
        // Midway along the lane, 1.5 m outside it (a corner's diagonal offset does not count).
        val horizontal = from.second == to.second
        val x = if (horizontal) {
            (a.x + b.x) / 2
        } else {
            (
                if (from.first == 0) {
                    -PARK_OFFSET
                } else {
                    (width - 1) * SPACING + PARK_OFFSET
                }
                )
        }
        val y = if (horizontal) {
            (
                if (from.second == 0) {
                    -PARK_OFFSET
                } else {
                    (height - 1) * SPACING + PARK_OFFSET
                }
                )
        } else {
            (a.y + b.y) / 2
        }
        return Position(x, y, 0)
    }

    companion object {
        /** Vehicle number [number] of a benchmark plant: 1 m long, 1 m/s, starting in its park [bay]. */
        fun benchmarkVehicle(number: Int, bay: String): Vehicle = Vehicle(
            "Vehicle-%03d".format(number),
            maxVelocity = SPEED,
            maxReverseVelocity = SPEED,
            boundingBox = BoundingBox(length = VEHICLE_LENGTH),
            properties = mapOf(Fleet.INITIAL_POSITION to bay),
        )

        /** The transfer stations of the benchmark plants: Load cargo and Unload cargo. */
        fun transferStationType(): LocationType = LocationType(
            TRANSFER_TYPE,
            setOf(GridPlant.LOAD, GridPlant.UNLOAD),
            layout = LocationTypeLayout(LocationRepresentation.LOAD_TRANSFER_GENERIC),
        )

        const val TRANSFER_TYPE = "Transfer station"
        const val SPACING = 2_000L
        const val STATION_OFFSET = 1_000L
        const val PARK_OFFSET = 1_500L
        const val STATION_EVERY = 4
        const val SPEED = 1_000
        const val VEHICLE_LENGTH = 1_000L
    }
}
