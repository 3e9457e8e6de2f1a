package org.ktcs.kernel.simulation

import org.ktcs.api.model.Link
import org.ktcs.api.model.Location
import org.ktcs.api.model.Path
import org.ktcs.api.model.PlantModel
import org.ktcs.api.model.Point
import org.ktcs.api.model.PointType
import org.ktcs.api.model.Pose
import org.ktcs.api.model.Position

/**
 * A warehouse-style plant: [aisles] two-way aisles of [depth] points (2 m apart, 4 m between aisles) joined by a
 * two-way cross aisle at each end. Transfer stations (Load cargo / Unload cargo) sit at the end of dead-end stubs
 * (1.5 m, two-way) beside every second aisle point; each of the [vehicles] vehicles (1 m long, 1 m/s) has a
 * dead-end park bay of its own beside a cross aisle and starts there. Vehicles meet head-on in the aisles and must
 * leave a station the way they came: the plant deadlock avoidance has to handle that a one-way grid does not.
 */
class WarehousePlant(private val aisles: Int, private val depth: Int, private val vehicles: Int) {
    private val points = ArrayList<Point>()
    private val paths = ArrayList<Path>()

    init {
        require(aisles >= 2 && depth >= 3) { "a warehouse needs at least 2 aisles of 3 points, got ${aisles}x$depth" }
        require(vehicles >= 1) { "a warehouse needs at least 1 vehicle, got $vehicles" }
        require(vehicles <= 2 * crossPoints()) {
            "a ${aisles}x$depth warehouse has room for ${2 * crossPoints()} park bays, not $vehicles vehicles"
        }
    }

    fun build(): PlantModel {
        val columns = crossPoints()
        for (y in 1 until depth - 1) for (a in 0 until aisles) point(aisle(a, y), a * AISLE_GAP, y * SPACING)
        for (c in 0 until columns) {
            point(cross(c, 0), c * SPACING, 0)
            point(cross(c, 1), c * SPACING, (depth - 1) * SPACING)
            if (c > 0) {
                twoWay(cross(c - 1, 0), cross(c, 0), SPACING)
                twoWay(cross(c - 1, 1), cross(c, 1), SPACING)
            }
        }
        for (a in 0 until aisles) {
            val column = (0 until depth).map { y -> aislePoint(a, y) }
            column.zipWithNext { from, to -> twoWay(from, to, SPACING) }
        }
        val locations = ArrayList<Location>()
        for (a in 0 until aisles) {
            for (y in 1 until depth - 1 step 2) {
                val stub = "Stub-%02d-%02d".format(a, y)
                point(stub, a * AISLE_GAP + STUB_LENGTH, y * SPACING)
                twoWay(aisle(a, y), stub, STUB_LENGTH)
                val position = Position(a * AISLE_GAP + STUB_LENGTH + 500, y * SPACING, 0)
                locations +=
                    Location("Station-%02d-%02d".format(a, y), TrafficGrid.TRANSFER_TYPE, position, listOf(Link(stub)))
            }
        }
        val fleet = (0 until vehicles).map { n ->
            val side = n % 2
            val c = (n / 2) * columns / ((vehicles + 1) / 2)
            val bay = "Park-%03d".format(n + 1)
            val y = if (side == 0) -STUB_LENGTH else (depth - 1) * SPACING + STUB_LENGTH
            point(bay, c * SPACING, y, PointType.PARK_POSITION)
            twoWay(cross(c, side), bay, STUB_LENGTH)
            TrafficGrid.benchmarkVehicle(n + 1, bay)
        }
        return PlantModel(
            name = "Warehouse ${aisles}x$depth, $vehicles vehicles",
            points = points,
            paths = paths,
            locationTypes = listOf(TrafficGrid.transferStationType()),
            locations = locations,
            vehicles = fleet,
        )
    }

    private fun crossPoints() = (aisles - 1) * (AISLE_GAP / SPACING).toInt() + 1

    private fun aislePoint(a: Int, y: Int): String = when (y) {
        0 -> cross(a * (AISLE_GAP / SPACING).toInt(), 0)
        depth - 1 -> cross(a * (AISLE_GAP / SPACING).toInt(), 1)
        else -> aisle(a, y)
    }

    private fun aisle(a: Int, y: Int) = "A-%02d-%02d".format(a, y)

    private fun cross(c: Int, end: Int) = "%s-%03d".format(if (end == 0) "S" else "N", c)

    private fun point(name: String, x: Long, y: Long, type: PointType = PointType.HALT_POSITION) {
        points += Point(name, Pose(Position(x, y, 0)), type)
    }

    private fun twoWay(from: String, to: String, length: Long) {
        paths +=
            Path(
                "$from --- $to",
                from,
                to,
                length,
                maxVelocity = TrafficGrid.SPEED,
                maxReverseVelocity = TrafficGrid.SPEED,
            )
    }

    private companion object {
        const val SPACING = 2_000L
        const val AISLE_GAP = 4_000L
        const val STUB_LENGTH = 1_500L
    }
}
