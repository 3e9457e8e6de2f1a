package org.ktcs.e2e.plant

/** The resources allocated to each vehicle, updated event by event; reports any resource two vehicles hold. */
class AllocationLedger {
    private val allocated = mutableMapOf<String, Set<String>>()

    /** Records that [vehicle] now holds exactly [resources]; returns each resource now held by more than one. */
    fun update(vehicle: String, resources: Set<String>): List<String> {
        allocated[vehicle] = resources
        return resources.mapNotNull { resource ->
            val holders = allocated.filterValues { resource in it }.keys.sorted()
            if (holders.size > 1) "$resource held by $holders" else null
        }
    }
}
