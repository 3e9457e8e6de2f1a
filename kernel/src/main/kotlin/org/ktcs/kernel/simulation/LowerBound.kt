package org.ktcs.kernel.simulation

import org.ktcs.api.model.PlantModel
import org.ktcs.kernel.routing.DefaultRouter
import org.ktcs.kernel.routing.EdgeEvaluator
import org.ktcs.kernel.routing.RouterConfiguration

/** One load/unload order as the [LowerBound] sees it: where it loads and unloads, with which operations. */
data class Trip(val from: String, val loadOperation: String, val to: String, val unloadOperation: String)

/**
 * A lower bound of a batch's makespan in simulated seconds: the sum over orders of the quickest drive from the load
 * station to the unload station (path length over the lower of path and vehicle speed, as the kernel's router rates
 * it with TRAVELTIME costs, no acceleration) plus both operations, divided by the number of vehicles. No fleet can do
 * better: it would have to drive straight at full speed, never wait and never drive empty.
 */
class LowerBound(private val model: PlantModel, private val operatingMillis: Long) {
    private val router = DefaultRouter(
        RouterConfiguration(edgeEvaluators = listOf(EdgeEvaluator.TRAVELTIME), operationPointSurcharge = 0),
    ).also { it.updateTopology(model) }
    private val vehicle = model.vehicles.maxByOrNull { it.maxVelocity }
    private val costsFrom = HashMap<String, (String) -> Long?>()

    /** The bound for [trips] on [vehicles] vehicles, `null` if the plant has no vehicle or a trip has no route. */
    fun seconds(trips: List<Trip>, vehicles: Int): Double? {
        if (vehicle == null || vehicles < 1) return null
        var totalMillis = 0.0
        for (trip in trips) totalMillis += (travelMillis(trip) ?: return null) + 2 * operatingMillis
        return totalMillis / vehicles / MILLIS_PER_SECOND
    }

    private fun travelMillis(trip: Trip): Long? {
        val starts = linkedPoints(trip.from, trip.loadOperation)
        val ends = linkedPoints(trip.to, trip.unloadOperation)
        return starts.flatMap { start ->
            val costs = costsFrom.getOrPut(start) { router.costsFrom(vehicle!!, start) }
            ends.mapNotNull { costs(it) }
        }.minOrNull()
    }

    private fun linkedPoints(location: String, operation: String): List<String> =
        model.location(location)?.links.orEmpty()
            .filter { it.allowedOperations.isEmpty() || operation in it.allowedOperations }
            .map { it.point }

    private companion object {
        const val MILLIS_PER_SECOND = 1000.0
    }
}
