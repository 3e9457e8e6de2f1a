package org.ktcs.kernel.dispatching

import org.ktcs.api.dispatching.DispatchContext
import org.ktcs.api.error.IllegalStateChangeException
import org.ktcs.api.kernel.Explained
import org.ktcs.api.model.PlantModel
import org.ktcs.api.model.ProcState
import org.ktcs.api.model.Vehicle
import org.ktcs.api.order.DriveOrder
import org.ktcs.api.order.OrderSequence
import org.ktcs.api.order.TransportOrder
import org.ktcs.api.order.TransportOrderCreation
import org.ktcs.api.order.TransportOrderState

/** An assignment the dispatcher made. */
data class Assignment(val order: String, val vehicle: String, val driveOrders: List<DriveOrder>)

/**
 * A [DispatchContext] over plain maps that records what the dispatcher does. Assigning updates the order and the
 * vehicle as the kernel would (withdrawing a dispensable order the vehicle was busy with), so a second run sees the
 * result of the first.
 */
class FakeDispatchContext(var model: PlantModel) : DispatchContext {
    override val clock = FakeClock()
    override val router = FakeRouter { model }

    val vehicles = LinkedHashMap<String, Vehicle>()
    val orders = LinkedHashMap<String, TransportOrder>()
    val sequences = LinkedHashMap<String, OrderSequence>()
    val assignments = mutableListOf<Assignment>()
    val created = mutableListOf<TransportOrder>()
    val deferrals = mutableListOf<Pair<String, String>>()
    val withdrawn = mutableListOf<String>()
    var driver: (vehicle: String, order: TransportOrder) -> Explained = { _, _ -> Explained.YES }

    /** Orders the kernel refuses to assign, as if they changed state in the meantime. */
    val refusedOrders = mutableSetOf<String>()
    private var nextSuffix = 1

    /** Adds or replaces vehicles, orders and sequences. */
    fun add(vararg objects: Any) = objects.forEach {
        when (it) {
            is Vehicle -> vehicles[it.name] = it
            is TransportOrder -> orders[it.name] = it
            is OrderSequence -> sequences[it.name] = it
            else -> error("cannot add $it")
        }
    }

    /** Orders assigned to [vehicle], in assignment order. */
    fun assignedTo(vehicle: String): List<String> = assignments.filter { it.vehicle == vehicle }.map { it.order }

    fun assignedOrder(vehicle: String): String? = assignedTo(vehicle).singleOrNull()

    fun deferralsOf(order: String): List<String> = deferrals.filter { it.first == order }.map { it.second }

    override fun plantModel(): PlantModel = model

    override fun vehicles(): Collection<Vehicle> = vehicles.values

    /** How often the dispatcher read the dispatchable orders. */
    var dispatchableReads = 0
        private set

    override fun dispatchableOrders(): Collection<TransportOrder> {
        dispatchableReads++
        return orders.values.filter { it.state == TransportOrderState.DISPATCHABLE }.sortedBy { it.creationTime }
    }

    override fun transportOrder(name: String): TransportOrder? = orders[name]

    override fun orderSequence(name: String): OrderSequence? = sequences[name]

    override fun driverAccepts(vehicle: String, order: TransportOrder): Explained = driver(vehicle, order)

    override fun assign(order: String, vehicle: String, driveOrders: List<DriveOrder>) {
        if (order in refusedOrders) throw IllegalStateChangeException("order $order cannot be assigned")
        val current = orders.getValue(order)
        check(current.state == TransportOrderState.DISPATCHABLE) { "order $order is ${current.state}" }
        check(driveOrders.all { it.route != null }) { "order $order assigned without routes" }
        assignments += Assignment(order, vehicle, driveOrders)
        val busy = vehicles.getValue(vehicle).transportOrder
        if (busy != null) {
            check(orders.getValue(busy).dispensable) { "vehicle $vehicle is busy with $busy" }
            withdrawn += busy
            orders[busy] = orders.getValue(busy).copy(state = TransportOrderState.WITHDRAWN)
        }
        orders[order] = current.copy(
            state = TransportOrderState.BEING_PROCESSED,
            processingVehicle = vehicle,
            driveOrders = driveOrders,
        )
        vehicles[vehicle] =
            vehicles.getValue(vehicle).copy(transportOrder = order, procState = ProcState.PROCESSING_ORDER)
    }

    override fun createTransportOrder(creation: TransportOrderCreation): TransportOrder {
        val name = if (creation.incompleteName) creation.name + "%02d".format(nextSuffix++) else creation.name
        val order = TransportOrder(
            name = name,
            driveOrders = creation.destinations.mapIndexed { index, it -> DriveOrder("Drive-$index", it) },
            type = creation.type,
            state = TransportOrderState.DISPATCHABLE,
            creationTime = clock.now(),
            deadline = creation.deadline,
            intendedVehicle = creation.intendedVehicle,
            dispensable = creation.dispensable,
            properties = creation.properties,
        )
        orders[name] = order
        created += order
        return order
    }

    /** The latest reason per vehicle, as [vehicleWaiting] gave it. */
    val vehicleReasons = HashMap<String, String?>()

    override fun vehicleWaiting(vehicle: String, reason: String?) {
        vehicleReasons[vehicle] = reason
    }

    override fun orderWaiting(order: String, reason: String) {
        deferrals += order to reason
    }
}
