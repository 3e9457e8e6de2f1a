package org.ktcs.kernel.scheduling

import org.ktcs.api.scheduling.SchedulerClient

/** A [SchedulerClient] that records its grants and accepts them while [accepts] is true. */
open class RecordingClient(override val name: String, var accepts: Boolean = true) : SchedulerClient {
    val granted = mutableListOf<Set<String>>()

    override fun onAllocationGranted(resources: Set<String>): Boolean {
        granted += resources
        return accepts
    }

    override fun toString(): String = name
}
