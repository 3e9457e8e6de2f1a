package org.ktcs.e2e.extensions

import org.koin.core.module.Module
import org.koin.dsl.module
import org.ktcs.api.dispatching.DispatchContext
import org.ktcs.api.dispatching.Dispatcher
import org.ktcs.api.model.IntegrationLevel
import org.ktcs.api.model.ProcState
import org.ktcs.extension.KtcsExtension
import org.ktcs.kernel.core.KernelCore

/** A replacement dispatcher: every order goes to the idle vehicle with the smallest name. Nothing else. */
class FirstIdleVehicleDispatcher(private val context: DispatchContext) : Dispatcher {
    var assignments = 0
        private set

    override fun dispatch() {
        for (order in context.dispatchableOrders().toList()) {
            val vehicle = context.vehicles()
                .filter {
                    it.integrationLevel == IntegrationLevel.TO_BE_UTILIZED && it.procState == ProcState.IDLE &&
                        it.transportOrder == null
                }
                .filter { it.currentPosition != null }
                .minByOrNull { it.name } ?: return
            val driveOrders = context.router.routeOrder(vehicle, vehicle.currentPosition!!, order) ?: continue
            context.assign(order.name, vehicle.name, driveOrders)
            assignments++
        }
    }
}

/** Swaps the dispatcher in, found through META-INF/services like any extension jar. */
class FirstIdleVehicleDispatcherExtension : KtcsExtension {
    override val name = "first-idle-vehicle-dispatcher"

    override fun module(): Module = module {
        single<Dispatcher> { FirstIdleVehicleDispatcher(get<KernelCore>().dispatchContext) }
    }
}
