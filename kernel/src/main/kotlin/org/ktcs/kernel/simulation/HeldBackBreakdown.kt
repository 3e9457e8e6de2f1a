package org.ktcs.kernel.simulation

import org.ktcs.api.model.PlantModel
import org.ktcs.api.model.Vehicle
import org.ktcs.api.model.VehicleState
import org.ktcs.kernel.routing.pointsLinkedToLocations
import org.ktcs.kernel.scheduling.DefaultScheduler
import org.ktcs.kernel.scheduling.GrantWait

/**
 * Where the held-back time of a simulated batch goes. Sampled at a fixed period of kernel time, each vehicle that holds
 * a batch order but is not executing counts once:
 * - by why its next grant waits ([GrantWait]; for an occupied resource, by what the holder does);
 * - by where it stands (on a generated grid: at a station, on the ring, or inside at some distance from the ring);
 * - by the *root* of its queue: following "waits for a point held by a held-back vehicle" to the first vehicle of
 *   the queue, what that one waits for and where it stands, and whether the queue is longer than [LONG_QUEUE].
 *
 * Kernel context; a sample costs the held-back vehicles and their queues, not the plant.
 */
class HeldBackBreakdown(model: PlantModel, private val scheduler: DefaultScheduler) {
    private val coordinates = model.points.mapNotNull { point -> gridCoordinates(point.name)?.let { point.name to it } }
        .toMap()
    private val maxX = coordinates.values.maxOfOrNull { it.first } ?: 0
    private val maxY = coordinates.values.maxOfOrNull { it.second } ?: 0
    private val stations = model.pointsLinkedToLocations()
    private val places = HashMap<String?, String>()
    private val byReason = HashMap<String, Long>()
    private val byPlace = HashMap<String, Long>()
    private val byRoot = HashMap<String, Long>()

    /** Counts the vehicles held back now; [vehicles] is the fleet, [inBatch] tells the batch's orders. */
    fun sample(vehicles: Collection<Vehicle>, inBatch: (String) -> Boolean) {
        val fleet = vehicles.associateBy { it.name }
        for (vehicle in vehicles) {
            val order = vehicle.transportOrder ?: continue
            if (!inBatch(order) || vehicle.state == VehicleState.EXECUTING) continue
            byReason.merge(reasonOf(vehicle.name, fleet), 1, Long::plus)
            byPlace.merge(placeOf(vehicle), 1, Long::plus)
            byRoot.merge(rootOf(vehicle, fleet), 1, Long::plus)
        }
    }

    /** The output lines: shares of the held-back samples by reason, by place and by the root of their queue. */
    fun lines(): List<String> {
        val total = byReason.values.sum().coerceAtLeast(1)
        fun shares(counts: Map<String, Long>) = counts.entries.sortedByDescending { it.value }
            .filter { it.value * 1000 >= total }
            .joinToString(", ") { "${it.key} ${"%.1f".format(it.value * 100.0 / total)}%" }
        return listOf(
            "held_back_by_reason: ${shares(byReason)}",
            "held_back_by_place: ${shares(byPlace)}",
            "held_back_by_queue_root: ${shares(byRoot)}",
        )
    }

    private fun reasonOf(vehicle: String, fleet: Map<String, Vehicle>): String {
        val (wait, holders) = scheduler.grantWaitOf(vehicle)
        if (wait != GrantWait.OCCUPIED) return wait.label
        val holder = holders.firstNotNullOfOrNull(fleet::get) ?: return "occupied_by_other"
        return when {
            holder.transportOrder == null -> "occupied_by_idle"
            holder.state != VehicleState.EXECUTING -> "occupied_by_held"
            holder.currentPosition in stations -> "occupied_by_operating_or_leaving_station"
            else -> "occupied_by_driving"
        }
    }

    // The first vehicle of [vehicle]'s queue: what it waits for, where it stands, and whether the queue is long.
    private fun rootOf(vehicle: Vehicle, fleet: Map<String, Vehicle>): String {
        val queue = HashSet<String>()
        var first = vehicle
        var cycle = false
        while (!cycle) {
            queue += first.name
            val (wait, holders) = scheduler.grantWaitOf(first.name)
            val holder = holders.firstNotNullOfOrNull(fleet::get)
            if (wait != GrantWait.OCCUPIED || holder == null) break
            if (holder.transportOrder == null || holder.state == VehicleState.EXECUTING) break
            cycle = holder.name in queue
            first = holder
        }
        val reason = if (cycle) "cycle" else reasonOf(first.name, fleet)
        val length = if (queue.size > LONG_QUEUE) "long" else "short"
        return "${reason}_at_${placeOf(first)}_$length"
    }

    private fun placeOf(vehicle: Vehicle): String =
        places.getOrPut(vehicle.currentPosition) { placeOf(vehicle.currentPosition) }

    private fun placeOf(point: String?): String {
        if (point in stations) return "station"
        val (x, y) = point?.let(coordinates::get) ?: return "off_grid"
        val fromRing = minOf(x, y, maxX - x, maxY - y)
        return when {
            fromRing == 0 -> "ring"
            fromRing <= NEAR_RING -> "interior_$fromRing"
            else -> "interior_deeper"
        }
    }

    private companion object {
        /** Queues of more than this many held-back vehicles count as long. */
        const val LONG_QUEUE = 5

        /** Inside the ring, the rows and columns up to this far from it are told apart. */
        const val NEAR_RING = 3
        val GRID_POINT = Regex("""P-(\d+)-(\d+)""")

        fun gridCoordinates(name: String): Pair<Int, Int>? =
            GRID_POINT.matchEntire(name)?.destructured?.let { (x, y) -> x.toInt() to y.toInt() }
    }
}
