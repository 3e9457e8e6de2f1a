package org.ktcs.kernel.services

import kotlinx.coroutines.flow.Flow
import kotlinx.coroutines.flow.consumeAsFlow
import kotlinx.coroutines.flow.emitAll
import kotlinx.coroutines.flow.flow
import org.ktcs.api.event.KernelEvent
import org.ktcs.api.event.UserNotification
import org.ktcs.api.order.Route
import org.ktcs.api.service.DispatcherService
import org.ktcs.api.service.KernelServices
import org.ktcs.api.service.NotificationService
import org.ktcs.api.service.PlantModelService
import org.ktcs.api.service.RouterService
import org.ktcs.api.service.TransportOrderService
import org.ktcs.api.service.VehicleService
import org.ktcs.kernel.core.KernelCore
import org.ktcs.kernel.persistence.PublishedModelFile

/**
 * The kernel's services, each call carried into the kernel context. A model that replaces the plant is saved to
 * [published] first (when given), so the next start runs it.
 */
class StandardKernelServices(
    private val kernel: KernelCore,
    published: PublishedModelFile? = null,
) : KernelServices {
    override val transportOrders: TransportOrderService = StandardTransportOrderService(kernel)
    override val dispatcher: DispatcherService = StandardDispatcherService(kernel)
    override val vehicles: VehicleService = StandardVehicleService(kernel)
    override val plantModel: PlantModelService = StandardPlantModelService(kernel, published)

    override val notifications: NotificationService = object : NotificationService {
        override suspend fun publish(
            notification: UserNotification,
        ) = kernel.context.call { kernel.publishNotification(notification) }

        override suspend fun notifications(): List<UserNotification> = kernel.context.call {
            kernel.notifications.recent()
        }
    }

    override val router: RouterService = object : RouterService {
        override suspend fun computeRoutes(
            vehicle: String,
            sourcePoint: String?,
            destinationPoints: List<String>,
            resourcesToAvoid: Set<String>,
            maxRoutes: Int,
        ): Map<String, List<Route>> = kernel.context.call {
            kernel.requests.routes(vehicle, sourcePoint, destinationPoints, resourcesToAvoid, maxRoutes)
        }
    }

    override fun events(): Flow<KernelEvent> = flow { emitAll(kernel.events.subscribe().consumeAsFlow()) }

    override suspend fun <T> eventsAfter(
        snapshot: suspend () -> T,
    ): Pair<T, Flow<KernelEvent>> = kernel.context.callAtomically {
        val subscription = kernel.events.subscribe()
        val taken = try {
            snapshot()
        } catch (error: Throwable) {
            subscription.cancel()
            throw error
        }
        taken to subscription.consumeAsFlow()
    }
}
