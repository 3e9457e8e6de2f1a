package org.ktcs.kernel.vehicles

import org.ktcs.api.routing.Router
import org.ktcs.api.scheduling.Scheduler
import org.ktcs.kernel.context.KernelContext
import org.ktcs.kernel.events.EventBus
import org.ktcs.kernel.events.Notifications
import org.ktcs.kernel.orders.TransportOrderPool
import org.ktcs.kernel.workingset.PlantState

/** What vehicle controllers share of the kernel. */
class VehicleEnvironment(
    val context: KernelContext,
    val events: EventBus,
    val plant: PlantState,
    val orders: TransportOrderPool,
    val notifications: Notifications,
    val scheduler: () -> Scheduler,
    val router: () -> Router,
    /** Called when a vehicle may have become free for work, so the dispatcher runs. */
    val vehicleMayBeAvailable: () -> Unit,
    val resourceManagement: ResourceManagement = ResourceManagement.LENGTH_RESPECTED,
    /** Notify when a vehicle reports a point that is not on the route it was sent (openTCS's watchdog). */
    val reportPositionOffRoute: Boolean = true,
)

/** How resources behind a vehicle are given back (openTCS: kernelapp.vehicleResourceManagementType). */
enum class ResourceManagement {
    /** Keep the paths behind the vehicle that its length still covers (openTCS's classic behaviour). */
    LENGTH_RESPECTED,

    /** Give back everything behind the point the vehicle stands on. */
    LENGTH_IGNORED,
}
