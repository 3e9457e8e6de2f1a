package org.ktcs.kernel.scheduling

// What deadlock avoidance reads from the steps of a claimed route. A step's resources are its path, the point it ends
// at and maybe a location.

/** The point [step] ends at. */
internal fun RouteSafety.pointOf(step: Set<String>): String? = step.lastOrNull(::isPoint)

/**
 * Per step of [route], the point where the vehicle stops at its end (null: it drives on): for an operation, or to turn
 * back the way it came (the dead-end park bay of a retreat). Standing there it waits only for the way out, so a retreat
 * is judged by its way into the bay; the way back out is judged when the vehicle asks for it, from the bay.
 */
internal fun RouteSafety.stopsOf(route: List<Set<String>>): List<String?> =
    route.mapIndexed { i, step ->
        if (step.any(::isLocation) || turnsBack(route, i)) pointOf(step) else null
    }

private fun RouteSafety.turnsBack(route: List<Set<String>>, i: Int): Boolean {
    val next = route.getOrNull(i + 1) ?: return false
    val path = pathOf(route[i])
    return (path != null && path == pathOf(next)) || (i > 0 && pointOf(next) == pointOf(route[i - 1]))
}

private fun RouteSafety.pathOf(step: Set<String>): String? = step.firstOrNull { !isPoint(it) && !isLocation(it) }
