package org.ktcs.kernel.simulation

import org.ktcs.api.model.PlantModel
import org.ktcs.api.order.TransportOrderCreation
import org.ktcs.kernel.config.KtcsConfig
import org.ktcs.kernel.config.KtcsSettings
import java.util.PriorityQueue

/**
 * A lower bound for the makespan of a batch of load/unload orders: the sum over the orders of the shortest travel
 * time from the load to the unload location plus both operation times, divided by the number of vehicles (no vehicle
 * can do better than drive straight at full speed and never wait or drive empty).
 */
class LowerBound(private val model: PlantModel, config: KtcsConfig) {
    private val operationSeconds = config[KtcsSettings.loopbackOperatingTime] / 1000.0
    private val speed = model.vehicles.maxOfOrNull { it.maxVelocity }?.takeIf { it > 0 } ?: DEFAULT_VELOCITY
    private val out = HashMap<String, MutableList<Pair<String, Double>>>().apply {
        for (path in model.paths) {
            val forward = minOf(path.maxVelocity, speed)
            val reverse = minOf(path.maxReverseVelocity, speed)
            if (forward >
                0
            ) {
                getOrPut(path.sourcePoint, ::ArrayList) += path.destinationPoint to path.length / forward.toDouble()
            }
            if (reverse >
                0
            ) {
                getOrPut(path.destinationPoint, ::ArrayList) += path.sourcePoint to path.length / reverse.toDouble()
            }
        }
    }
    private val cache = HashMap<String, Map<String, Double>>()

    fun seconds(orders: List<TransportOrderCreation>): Double {
        val vehicles = model.vehicles.size.coerceAtLeast(1)
        return orders.sumOf { order ->
            val (load, unload) = order.destinations.map { it.target }
            travelSeconds(load, unload) + 2 * operationSeconds
        } / vehicles
    }

    // Shortest time between any point linked to one location and any point linked to the other.
    private fun travelSeconds(from: String, to: String): Double {
        val targets = pointsOf(to)
        return pointsOf(from).minOf { start ->
            val times = cache.getOrPut(start) { fastestFrom(start) }
            targets.minOf { times[it] ?: Double.POSITIVE_INFINITY }
        }.takeIf { it.isFinite() } ?: 0.0
    }

    private fun pointsOf(target: String): List<String> =
        model.location(target)?.links?.map { it.point } ?: listOf(target)

    private fun fastestFrom(start: String): Map<String, Double> {
        val best = HashMap<String, Double>().apply { put(start, 0.0) }
        val queue = PriorityQueue<Pair<String, Double>>(compareBy { it.second }).apply { add(start to 0.0) }
        while (queue.isNotEmpty()) {
            val (point, time) = queue.poll()
            if (time > best.getValue(point)) continue
            for ((next, cost) in out[point].orEmpty()) {
                val arrival = time + cost
                if (arrival < (best[next] ?: Double.POSITIVE_INFINITY)) {
                    best[next] = arrival
                    queue += next to arrival
                }
            }
        }
        return best
    }

    private companion object {
        const val DEFAULT_VELOCITY = 1000
    }
}
