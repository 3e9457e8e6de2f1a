package org.ktcs.kernel.scheduling

/**
 * Who stands in the dead-end station stub that [request] brings its vehicle into a two-way corridor towards, by the
 * stub: the vehicle then waits outside the corridor ([GrantWait.STATION_TAKEN]) instead of queueing at the stub's
 * mouth, where the vehicle inside, leaving the way it came, would meet it head-on (developer's guide, section 12).
 * Null if the step comes into no corridor, the vehicle already stands in a stub beside one (it is let out as any
 * vehicle inside is), or its next stop is free or outside the corridor.
 */
internal fun Occupancy.standingInStationAhead(request: Request, safety: RouteSafety): Map<String, Set<String>>? {
    val entering = request.gates.ifEmpty { request.corridors.filter { it.entering } }
    val client = request.client.name
    if (entering.isEmpty() || holdsAny(client, safety::isDeadEnd)) return null
    for (entry in entering) {
        val stub = safety.deadEndStopInside(client, request.keys, entry.block.members) ?: continue
        val others = holdersOf(stub).filter { it != client }
        if (others.isNotEmpty()) return others.associateWith { setOf(stub) }
    }
    return null
}

/**
 * Drops [client]'s gates ([Request.gates]) if it stands in a dead end ([isDeadEnd]: a station stub), where it waits
 * off the aisle for the way out the traffic rule holds back: the corridor is then free for the vehicles heading the
 * other way, which need not pass it. Returns the wake-up keys of the corridors it so left.
 */
internal fun Occupancy.openGatesInStub(client: String, isDeadEnd: (String) -> Boolean): Set<String> =
    if (holdsAny(client, isDeadEnd)) leaveGates(client) else emptySet()
