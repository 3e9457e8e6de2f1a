package org.ktcs.kernel.core

import org.ktcs.api.driver.VehicleDriverFactory
import org.ktcs.api.model.PlantModel
import org.ktcs.api.routing.Router
import org.ktcs.api.scheduling.Scheduler
import org.ktcs.kernel.context.KernelContext
import org.ktcs.kernel.events.EventBus
import org.ktcs.kernel.events.Notifications
import org.ktcs.kernel.orders.OrderSequencePool
import org.ktcs.kernel.orders.TransportOrderPool
import org.ktcs.kernel.vehicles.VehicleControllers
import org.ktcs.kernel.vehicles.VehicleEnvironment
import org.ktcs.kernel.workingset.ObjectNames
import org.ktcs.kernel.workingset.PlantState

/**
 * The kernel's mutable state. Only [KernelCore] holds it (privately) and hands it to the parts of `core` it builds;
 * everybody else reads through [KernelCore]'s read-only views and changes state through its operations, so every
 * rule about a change lives in `core`. Confined to the kernel [context].
 */
class KernelState(
    val context: KernelContext,
    model: PlantModel,
    options: KernelOptions,
    driverFactories: List<VehicleDriverFactory>,
    scheduler: () -> Scheduler,
    router: () -> Router,
    vehicleMayBeAvailable: () -> Unit,
) {
    val events = EventBus(context)
    val notifications = Notifications(events, context)
    val plant = PlantState(model, events)
    val orders = TransportOrderPool(events, context)
    val sequences = OrderSequencePool(events, context)
    val names = ObjectNames(context)
    val controllers = VehicleControllers(
        VehicleEnvironment(
            context,
            events,
            plant,
            orders,
            notifications,
            scheduler,
            router,
            vehicleMayBeAvailable,
            options.resourceManagement,
            options.watchdog.reportPositionOffRoute,
        ),
        driverFactories,
    )
}
