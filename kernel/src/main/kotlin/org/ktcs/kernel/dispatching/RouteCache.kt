package org.ktcs.kernel.dispatching

import org.ktcs.api.model.Vehicle
import org.ktcs.api.order.DriveOrder
import org.ktcs.api.order.TransportOrder
import org.ktcs.api.routing.Router

/**
 * The router's answers during one dispatch run, so no pair of vehicle and order (or point) is routed twice. Only valid
 * for one run: positions, locks and orders change between runs.
 */
internal class RouteCache(private val router: Router) {
    private data class Key(val vehicle: String, val source: String, val target: String)

    private val orderRoutes = HashMap<Key, List<DriveOrder>?>()
    private val costTrees = HashMap<Pair<String, String>, (String) -> Long?>()
    private val pointCosts = HashMap<Key, Long?>()

    /** [order]'s drive orders routed from [vehicle]'s position, or `null` if it has none or there is no route. */
    fun route(vehicle: Vehicle, order: TransportOrder): List<DriveOrder>? {
        val position = vehicle.currentPosition ?: return null
        return orderRoutes.memo(Key(vehicle.name, position, order.name)) { router.routeOrder(vehicle, position, order) }
    }

    /** The costs of the cheapest route from [vehicle]'s position to [point], or `null` if there is none. */
    fun costs(vehicle: Vehicle, point: String): Long? {
        val position = vehicle.currentPosition ?: return null
        return pointCosts.memo(Key(vehicle.name, position, point)) {
            costTrees.getOrPut(vehicle.name to position) { router.costsFrom(vehicle, position) }(point)
        }
    }

    /** The costs of the cheapest route from [vehicle]'s position to [point], from a search backwards from [point]. */
    fun costsTo(vehicle: Vehicle, point: String): Long? {
        val position = vehicle.currentPosition ?: return null
        return pointCosts.memo(Key(vehicle.name, position, point)) { router.costsTo(vehicle, point)(position) }
    }

    private inline fun <V> HashMap<Key, V?>.memo(key: Key, compute: () -> V?): V? =
        if (containsKey(key)) get(key) else compute().also { put(key, it) }
}
