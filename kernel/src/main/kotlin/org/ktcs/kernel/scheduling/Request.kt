package org.ktcs.kernel.scheduling

import org.ktcs.api.scheduling.SchedulerClient

/**
 * A client's request for resources, numbered in arrival order; [corridors] are the two-way corridors it drives along
 * ([Corridors]), each with the way it heads, and [gates] those the client's route comes into right after it: it may
 * take the corridor's end (which the vehicles driving out need) only once it may come in.
 */
internal class Request(
    val seq: Long,
    val client: SchedulerClient,
    val resources: Set<String>,
    val expanded: Set<String>,
    val entries: List<BlockEntry>,
    val corridors: List<BlockEntry> = emptyList(),
    val gates: List<BlockEntry> = emptyList(),
) {
    /** Its resources and the SAME_DIRECTION_ONLY blocks it touches: what holding the granted request means. */
    val physicalKeys: Set<String> = expanded + entries.map { it.block.name }

    /**
     * What the request may wait for: its [physicalKeys] and, per corridor it comes into or is let in at the end of
     * ([gates]), nobody using it the other way. Granted, it holds the way in for its heading ([RouteSafety]).
     */
    val keys: Set<String> = (corridors.filter { it.entering } + gates).let { heading ->
        if (heading.isEmpty()) {
            physicalKeys
        } else {
            physicalKeys + heading.map { Corridors.needKey(it.block.name, it.direction) }
        }
    }

    /**
     * The keys whose change may let the request through, for [PendingRequests]: its [keys] plus, per corridor it
     * touches or waits to come into ([gates]), the need key of the way it heads, whether or not it comes into it.
     * Whether a step comes into a corridor is decided when it is asked for; a vehicle inside then may have left by
     * the time the step is looked at again (it drove into a stub beside the corridor, covering the aisle point with
     * its length when it asked for the way back out), and then waits for the corridor's direction like any other.
     * The corridor's records give these keys back whenever its direction changes or a user leaves ([Occupancy]).
     */
    val wakeKeys: Set<String> =
        if (corridors.isEmpty() && gates.isEmpty()) {
            keys
        } else {
            keys + (corridors + gates).map { Corridors.needKey(it.block.name, it.direction) }
        }

    companion object {
        /** [client]'s request number [seq] for [resources], with the blocks and corridors they touch. */
        fun of(
            seq: Long,
            client: SchedulerClient,
            resources: Set<String>,
            blocks: BlockIndex,
            corridorSteps: CorridorSteps,
        ): Request {
            val requested = resources.toSet()
            val expanded = blocks.expand(requested)
            return Request(
                seq,
                client,
                requested,
                expanded,
                blocks.entries(expanded),
                corridorSteps.entries(client.name, requested),
                corridorSteps.gates(client.name, requested),
            )
        }
    }
}
