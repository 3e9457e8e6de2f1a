package org.ktcs.kernel.bench

import org.ktcs.api.model.PlantModel
import org.ktcs.kernel.routing.DefaultRouter
import org.ktcs.kernel.routing.EdgeEvaluator
import org.ktcs.kernel.routing.RouterConfiguration

/**
 * A lower bound of a batch's makespan in simulated seconds: the sum over orders of the quickest drive from the load
 * station to the unload station (path length over the lower of path and vehicle speed, as the kernel's router rates
 * it with TRAVELTIME costs, no acceleration) plus both operations, divided by the number of vehicles.
 */
class LowerBound(private val model: PlantModel, private val operatingMillis: Long) {
    private val router = DefaultRouter(RouterConfiguration(edgeEvaluators = listOf(EdgeEvaluator.TRAVELTIME))).also {
        it.updateTopology(model)
    }
    private val vehicle = model.vehicles.maxByOrNull { it.maxVelocity }
    private val costsFrom = HashMap<String, (String) -> Long?>()

    /** The bound for [orders] on [vehicles] vehicles, `null` if the plant has no vehicle or an order has no route. */
    fun seconds(orders: List<BenchOrder>, vehicles: Int): Double? {
        if (vehicle == null || vehicles < 1) return null
        var totalMillis = 0.0
        for (order in orders) totalMillis += (travelMillis(order.from, order.to) ?: return null) + 2 * operatingMillis
        return totalMillis / vehicles / MILLIS_PER_SECOND
    }

    private fun travelMillis(from: String, to: String): Long? {
        val starts = linkedPoints(from, BenchClient.LOAD)
        val ends = linkedPoints(to, BenchClient.UNLOAD)
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
