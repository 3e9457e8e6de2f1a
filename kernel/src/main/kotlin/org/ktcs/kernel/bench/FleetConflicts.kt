package org.ktcs.kernel.bench

/**
 * What the bench checks after every vehicle event, in kernel order: every moment a resource was allocated to two
 * vehicles, or two vehicles stood on one point. Each pair and resource (or point) counts once. Who holds each resource
 * and who stands on each point are kept, so a vehicle's event costs the resources it holds, not a pass over the whole
 * fleet: the bench shares the machine with the kTCS it measures.
 */
internal class FleetConflicts {
    /** A vehicle as an event shows it: the resources it holds and the point it stands on. */
    data class Standing(val name: String, val held: Set<String>, val position: String?)

    private val allocations = HashMap<String, Set<String>>()
    private val positions = HashMap<String, String?>()
    private val holders = HashMap<String, MutableSet<String>>()
    private val standing = HashMap<String, MutableSet<String>>()
    private val conflicts = HashSet<String>()
    private val shared = HashSet<String>()

    fun doubleAllocations(): Int = conflicts.size

    fun sharedPositions(): Int = shared.size

    /** What [name] holds as last seen. */
    fun held(name: String): Set<String> = allocations[name].orEmpty()

    /** The point the vehicle [name] stood on when it was last placed, if any. */
    fun position(name: String): String? = positions[name]

    /** A snapshot replaces the whole fleet at once: checking it vehicle by vehicle against older states would not. */
    fun snapshot(vehicles: List<Standing>) {
        allocations.clear()
        positions.clear()
        holders.clear()
        standing.clear()
        vehicles.forEach(::place)
        vehicles.forEach { check(it.name) }
    }

    /** One vehicle's new state. */
    fun vehicle(vehicle: Standing) {
        place(vehicle)
        check(vehicle.name)
    }

    private fun place(vehicle: Standing) {
        val name = vehicle.name
        val before = allocations.put(name, vehicle.held).orEmpty()
        for (resource in before) if (resource !in vehicle.held) holders[resource]?.remove(name)
        for (resource in vehicle.held) holders.getOrPut(resource, ::HashSet) += name
        val was = positions.put(name, vehicle.position)
        if (was != vehicle.position) {
            was?.let { standing[it]?.remove(name) }
            vehicle.position?.let { standing.getOrPut(it, ::HashSet) += name }
        }
    }

    private fun check(name: String) {
        for (resource in allocations[name].orEmpty()) {
            for (other in holders[resource].orEmpty()) if (other != name) conflicts += key(name, other, resource)
        }
        val position = positions[name] ?: return
        for (other in standing[position].orEmpty()) if (other != name) shared += key(name, other, position)
    }

    private fun key(a: String, b: String, what: String) = "${minOf(a, b)}|${maxOf(a, b)}|$what"
}
