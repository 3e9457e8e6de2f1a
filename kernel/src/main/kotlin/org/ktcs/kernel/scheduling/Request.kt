package org.ktcs.kernel.scheduling

import org.ktcs.api.scheduling.SchedulerClient

/** A client's request for resources, numbered in arrival order. */
internal class Request(
    val seq: Long,
    val client: SchedulerClient,
    val resources: Set<String>,
    val expanded: Set<String>,
    val entries: List<BlockEntry>,
) {
    /** What the request may wait for: its resources and the SAME_DIRECTION_ONLY blocks it touches. */
    val keys: Set<String> = expanded + entries.map { it.block.name }
}
