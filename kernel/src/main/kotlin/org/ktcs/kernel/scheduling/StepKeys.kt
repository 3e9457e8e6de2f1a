package org.ktcs.kernel.scheduling

// The keys of a route step as deadlock avoidance ([RouteSafety]) counts them.

/** [keys] without corridor need keys: what holding a step means. */
internal fun physicalOf(keys: Set<String>): Set<String> =
    if (keys.none(Corridors::isDirectionKey)) keys else keys.filterNotTo(HashSet(), Corridors::isDirectionKey)

/**
 * What a grantee holds, as deadlock avoidance counts it, once it has driven up to a grant of [keys]: the step's
 * resources, what its length covers behind ([behind], whose corridor keys the step's own stand for) and, per corridor
 * it heads along, the ways in for vehicles heading the other way.
 */
internal fun keysHeldAfter(keys: Set<String>, behind: Set<String>): Set<String> {
    if (keys.none(Corridors::isDirectionKey) && behind.none(Corridors::isDirectionKey)) return keys + behind
    val held = HashSet(physicalOf(keys))
    held += physicalOf(behind)
    for (key in keys.filter(Corridors::isDirectionKey)) {
        held += Corridors.heldKeys(Corridors.blockOfKey(key), Corridors.directionOfKey(key))
    }
    return held
}
