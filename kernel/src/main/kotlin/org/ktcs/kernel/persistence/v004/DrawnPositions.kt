package org.ktcs.kernel.persistence.v004

import org.ktcs.api.model.Couple
import org.ktcs.api.model.Location
import org.ktcs.api.model.Point
import org.ktcs.api.model.Position
import org.ktcs.kernel.persistence.ReadWarnings

/**
 * Files older than 6.0.0 keep two coordinates per point and location: the model position and the layout position
 * openTCS's plant overview drew it at. Path control points and, in many files, location positions are in the layout's
 * system, so where the two disagree (openTCS 5.0's Demo-01 is an example) kTCS uses the drawn position for every
 * element and says so once, naming the elements: otherwise paths are drawn as long loops between points that moved.
 * Path lengths are unaffected; they are in the file.
 */
internal class DrawnPositions(private val layouts: LegacyLayouts, private val warnings: ReadWarnings) {
    private val moved = mutableListOf<String>()
    private var total = 0

    fun point(point: Point, to: PointTO): Point {
        total++
        val drawn = layouts.drawnPosition(to) ?: return point
        val position = point.pose.position
        if (!differs(position, drawn)) return point
        moved += "point '${point.name}' model (${position.x},${position.y}) drawn (${drawn.x},${drawn.y})"
        return point.copy(pose = point.pose.copy(position = position.copy(x = drawn.x, y = drawn.y)))
    }

    fun location(location: Location, to: LocationTO): Location {
        total++
        val drawn = layouts.drawnPosition(to) ?: return location
        val position = location.position
        if (!differs(position, drawn)) return location
        moved += "location '${location.name}' model (${position.x},${position.y}) drawn (${drawn.x},${drawn.y})"
        return location.copy(position = position.copy(x = drawn.x, y = drawn.y))
    }

    fun report() {
        if (moved.isEmpty()) return
        val examples = moved.take(EXAMPLES).joinToString("; ")
        val more = if (moved.size > EXAMPLES) "; and ${moved.size - EXAMPLES} more" else ""
        warnings.note(
            "visual layout",
            "${moved.size} of $total points and locations have a model position that differs from the layout " +
                "position openTCS's plant overview drew them at; kTCS uses the drawn positions so that points, " +
                "paths and locations agree ($examples$more)",
        )
    }

    private fun differs(position: Position, drawn: Couple) = position.x != drawn.x || position.y != drawn.y

    private companion object {
        const val EXAMPLES = 3
    }
}
