package org.ktcs.xmlchannels

import kotlinx.coroutines.flow.Flow
import kotlinx.coroutines.flow.MutableSharedFlow
import org.ktcs.api.error.ObjectUnknownException
import org.ktcs.api.event.KernelEvent
import org.ktcs.api.order.DriveOrder
import org.ktcs.api.order.OrderSequence
import org.ktcs.api.order.OrderSequenceCreation
import org.ktcs.api.order.TransportOrder
import org.ktcs.api.order.TransportOrderCreation
import org.ktcs.api.service.DispatcherService
import org.ktcs.api.service.KernelServices
import org.ktcs.api.service.NotificationService
import org.ktcs.api.service.PlantModelService
import org.ktcs.api.service.RouterService
import org.ktcs.api.service.TransportOrderService
import org.ktcs.api.service.VehicleService
import java.lang.reflect.Proxy
import java.time.Instant

/**
 * Kernel services for channel tests: orders are recorded, named `TOrder-0001`, … and refused for a location
 * or vehicle not in [plant]; events are whatever a test emits into [events].
 */
class FakeKernelServices(private val plant: FakePlant = FakePlant()) : KernelServices {
    val events = MutableSharedFlow<KernelEvent>()
    private val orders = FakeTransportOrders(plant)

    /** Every order created, in creation order. */
    val created: List<TransportOrder> get() = orders.created()

    override val transportOrders: TransportOrderService = orders
    override val dispatcher: DispatcherService = unsupported()
    override val vehicles: VehicleService = unsupported()
    override val plantModel: PlantModelService = unsupported()
    override val notifications: NotificationService = unsupported()
    override val router: RouterService = unsupported()

    override fun events(): Flow<KernelEvent> = events

    override suspend fun <T> eventsAfter(snapshot: suspend () -> T): Pair<T, Flow<KernelEvent>> = snapshot() to events
}

/** The names the fake kernel knows. */
data class FakePlant(
    val locations: Set<String> = setOf(
        "Storage 01", "Storage 02", "Working station 01", "Working station 02", "Working station 03",
        "TST8", "TST9", "TST11", "TST12",
    ),
    val vehicles: Set<String> = setOf("Vehicle-01"),
)

private class FakeTransportOrders(private val plant: FakePlant) : TransportOrderService {
    private val orders = mutableListOf<TransportOrder>()

    fun created(): List<TransportOrder> = synchronized(orders) { orders.toList() }

    override suspend fun createTransportOrder(creation: TransportOrderCreation): TransportOrder = synchronized(orders) {
        creation.destinations.map { it.target }.firstOrNull { it !in plant.locations }
            ?.let { throw ObjectUnknownException("unknown location '$it'") }
        creation.intendedVehicle?.takeIf { it !in plant.vehicles }
            ?.let { throw ObjectUnknownException("unknown vehicle '$it'") }
        creation.dependencies.firstOrNull { name -> orders.none { it.name == name } }
            ?.let { throw ObjectUnknownException("unknown order '$it'") }
        val name = if (creation.incompleteName) creation.name + "%04d".format(orders.size + 1) else creation.name
        creation.toOrder(name).also { orders += it }
    }

    override suspend fun transportOrder(name: String) = created().firstOrNull { it.name == name }

    override suspend fun transportOrders(intendedVehicle: String?) = created()

    override suspend fun setIntendedVehicle(order: String, vehicle: String?) = throw UnsupportedOperationException()

    override suspend fun createOrderSequence(creation: OrderSequenceCreation): OrderSequence =
        throw UnsupportedOperationException()

    override suspend fun orderSequence(name: String): OrderSequence? = null

    override suspend fun orderSequences(intendedVehicle: String?): List<OrderSequence> = emptyList()

    override suspend fun markOrderSequenceComplete(name: String) = throw UnsupportedOperationException()
}

fun TransportOrderCreation.toOrder(name: String) = TransportOrder(
    name = name,
    driveOrders = destinations.mapIndexed { index, destination -> DriveOrder("$name-$index", destination) },
    creationTime = Instant.EPOCH,
    deadline = deadline,
    intendedVehicle = intendedVehicle,
    dependencies = dependencies,
    properties = properties,
)

/** A service the channels must not use: every call fails. */
private inline fun <reified T : Any> unsupported(): T = Proxy.newProxyInstance(
    T::class.java.classLoader,
    arrayOf(T::class.java),
) {
        _,
        method,
        _,
    ->
    throw UnsupportedOperationException("${T::class.simpleName}.${method.name} is not for the XML channels")
} as T
