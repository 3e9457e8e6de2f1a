package org.ktcs.kernel.simulation

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

/**
 * Generates a warehouse-like plant of [width] × [height] crossings: rows and columns are one-way lanes in
 * alternating directions whose outer ring runs around the plant (so every crossing reaches every other). Transfer
 * stations sit in drive-through bays below the bottom row and above the top row, parking positions in bays left of
 * the left column, and recharge stations (every fourth row) and more parking in bays right of the right column.
 * Odd sizes get a two-way outermost lane to stay connected.
 */
class GridPlant(private val width: Int, private val height: Int, private val spacing: Long = 2_500) {
    init {
        require(width >= 2 && height >= 2) { "a grid needs at least 2×2 crossings, got ${width}x$height" }
    }

    private val points = mutableListOf<Point>()
    private val positions = HashMap<String, Position>()
    private val paths = mutableListOf<Path>()
    private val locations = mutableListOf<Location>()

    fun build(): PlantModel {
        for (y in 0 until height) {
            for (x in 0 until width) {
                addPoint(
                    crossing(x, y),
                    Position(x * spacing, y * spacing, 0),
                    PointType.HALT_POSITION,
                )
            }
        }
        for (y in 0 until height) {
            for (x in 0 until width - 1) {
                lane(
                    x,
                    y,
                    x + 1,
                    y,
                    eastbound(y),
                    twoWay =
                    height % 2 == 1 && y == height - 1,
                )
            }
        }
        for (x in 0 until width) {
            for (y in 0 until height - 1) {
                lane(
                    x,
                    y,
                    x,
                    y + 1,
                    northbound(x),
                    twoWay =
                    width % 2 == 1 && x == width - 1,
                )
            }
        }
        for (x in 0 until width - 1 step 2) {
            station("Station-S$x", crossing(x, 0), crossing(x + 1, 0), 0, -1)
            station("Station-N$x", crossing(x + 1, height - 1), crossing(x, height - 1), 0, 1)
        }
        for (y in 1 until height) {
            bay("Park-W$y", crossing(0, y), crossing(0, y - 1), -1, 0, PointType.PARK_POSITION)
        }
        for (y in 0 until height - 1) {
            val from = crossing(width - 1, y)
            val to = crossing(width - 1, y + 1)
            if (y % 4 == 1) {
                charger("Charger-E$y", from, to)
            } else {
                bay("Park-E$y", from, to, 1, 0, PointType.PARK_POSITION)
            }
        }
        return PlantModel(
            name = "Grid ${width}x$height",
            points = points,
            paths = paths,
            locationTypes = listOf(
                LocationType(
                    TRANSFER_TYPE,
                    setOf(LOAD, UNLOAD, "NOP"),
                    layout = LocationTypeLayout(LocationRepresentation.LOAD_TRANSFER_GENERIC),
                ),
                LocationType(
                    RECHARGE_TYPE,
                    setOf("CHARGE", "NOP"),
                    layout = LocationTypeLayout(LocationRepresentation.RECHARGE_GENERIC),
                ),
            ),
            locations = locations,
        )
    }

    // Row 0 runs east and rows alternate; column 0 runs south and columns alternate: the outer ring is a cycle.
    private fun eastbound(y: Int) = y % 2 == 0

    private fun northbound(x: Int) = x % 2 == 1

    private fun crossing(x: Int, y: Int) = "P-$x-$y"

    private fun lane(x1: Int, y1: Int, x2: Int, y2: Int, forward: Boolean, twoWay: Boolean) {
        val (from, to) = if (forward) crossing(x1, y1) to crossing(x2, y2) else crossing(x2, y2) to crossing(x1, y1)
        paths +=
            Path("$from --- $to", from, to, spacing, maxVelocity = 1000, maxReverseVelocity = if (twoWay) 1000 else 0)
    }

    /**
     * A drive-through bay beside the lane from [from] to [to]: vehicles enter it from [from] and leave it towards [to],
     * so a vehicle waiting to enter never blocks the one leaving.
     */
    private fun bay(name: String, from: String, to: String, dx: Int, dy: Int, type: PointType): String {
        val a = positions.getValue(from)
        val b = positions.getValue(to)
        addPoint(name, Position((a.x + b.x) / 2 + dx * spacing, (a.y + b.y) / 2 + dy * spacing, 0), type)
        paths += Path("$from --- $name", from, name, spacing, maxVelocity = 1000)
        paths += Path("$name --- $to", name, to, spacing, maxVelocity = 1000)
        return name
    }

    private fun addPoint(name: String, position: Position, type: PointType) {
        points += Point(name, Pose(position), type)
        positions[name] = position
    }

    private fun station(name: String, from: String, to: String, dx: Int, dy: Int) {
        val point = bay("$name-point", from, to, dx, dy, PointType.HALT_POSITION)
        locations += Location(name, TRANSFER_TYPE, beside(point, dx, dy), listOf(Link(point)))
    }

    private fun charger(name: String, from: String, to: String) {
        val point = bay("$name-point", from, to, 1, 0, PointType.HALT_POSITION)
        locations += Location(name, RECHARGE_TYPE, beside(point, 1, 0), listOf(Link(point)))
    }

    private fun beside(point: String, dx: Int, dy: Int): Position {
        val base = positions.getValue(point)
        return Position(base.x + dx * spacing / 2, base.y + dy * spacing / 2, 0)
    }

    companion object {
        const val TRANSFER_TYPE = "Transfer station"
        const val RECHARGE_TYPE = "Recharge station"
        const val LOAD = "Load cargo"
        const val UNLOAD = "Unload cargo"
    }
}
