package org.ktcs.kernel.simulation

import org.ktcs.api.model.Vehicle
import org.ktcs.api.order.DriveOrder
import org.ktcs.api.order.Route
import org.ktcs.api.order.TransportOrder
import org.ktcs.api.routing.Router

/** A router that records how long each route computation takes on the wall clock, in nanoseconds. */
class TimedRouter(private val router: Router) : Router by router {
    val durationsNanos = ArrayList<Long>()

    override fun routeOrder(vehicle: Vehicle, sourcePoint: String, order: TransportOrder): List<DriveOrder>? =
        timed { router.routeOrder(vehicle, sourcePoint, order) }

    override fun routes(
        vehicle: Vehicle,
        sourcePoint: String,
        destinationPoint: String,
        resourcesToAvoid: Set<String>,
        maxRoutes: Int,
    ): List<Route> =
        timed { router.routes(vehicle, sourcePoint, destinationPoint, resourcesToAvoid, maxRoutes) }

    override fun costsFrom(vehicle: Vehicle, sourcePoint: String): (String) -> Long? {
        val costs = router.costsFrom(vehicle, sourcePoint)
        return { destination -> timed { costs(destination) } }
    }

    override fun costsTo(vehicle: Vehicle, destinationPoint: String): (String) -> Long? {
        val costs = router.costsTo(vehicle, destinationPoint)
        return { source -> timed { costs(source) } }
    }

    private inline fun <T> timed(block: () -> T): T {
        val start = System.nanoTime()
        try {
            return block()
        } finally {
            durationsNanos += System.nanoTime() - start
        }
    }
}
