package org.ktcs.examples.clients

import kotlinx.coroutines.CoroutineStart
import kotlinx.coroutines.async
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.filterIsInstance
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.flow.mapNotNull
import org.ktcs.api.event.TransportOrderEvent
import org.ktcs.api.order.Destination
import org.ktcs.api.order.TransportOrder
import org.ktcs.api.order.TransportOrderCreation
import org.ktcs.api.service.KernelServices

/**
 * What [KtcsClient] does over HTTP, done inside the kTCS process with the kernel services, as an extension would
 * (`get<KernelServices>()` in its Koin module). Needs only the `api` module.
 */
class InProcessOrders(private val services: KernelServices) {
    // snippet:kernel-services-order
    /** Creates an order that loads at [from] and unloads at [to], and returns it once it is final. */
    suspend fun deliver(name: String, from: String, to: String): TransportOrder = coroutineScope {
        // Collect the events before creating the order, so that none of its changes is missed.
        val end = async(start = CoroutineStart.UNDISPATCHED) {
            services.events().filterIsInstance<TransportOrderEvent>()
                .mapNotNull { event -> event.current?.takeIf { it.name == name && it.state.isFinal } }
                .first()
        }
        val destinations = listOf(Destination(from, "Load cargo"), Destination(to, "Unload cargo"))
        services.transportOrders.createTransportOrder(TransportOrderCreation(name, destinations))
        end.await()
    }
    // end-snippet
}
