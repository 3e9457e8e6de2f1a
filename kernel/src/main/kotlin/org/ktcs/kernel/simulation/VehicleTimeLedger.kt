package org.ktcs.kernel.simulation

import org.ktcs.api.event.KernelEvent
import org.ktcs.api.event.TransportOrderEvent
import org.ktcs.api.event.VehicleEvent
import org.ktcs.api.model.Vehicle
import org.ktcs.api.model.VehicleState
import org.ktcs.api.order.TransportOrder
import org.ktcs.api.order.TransportOrderState
import java.util.EnumMap

/** What a vehicle spends its time on during a simulated batch of load/unload orders. */
enum class VehicleTimeUse(val label: String) {
    /** Driving an order's later drive orders: from the load station to the unload station. */
    DRIVING_LOADED("driving_loaded"),

    /** Driving an order's first drive order: empty, to the load station. */
    DRIVING_EMPTY("driving_empty"),

    /** Standing at a destination, performing its operation. */
    OPERATING("operating"),

    /** Holding an order but standing: waiting for the scheduler to grant the next step (or for commands). */
    HELD_BACK("held_back"),

    /** Processing an order of the kernel's own (park, recharge), moving or waiting. */
    PARKING("parking"),

    /** Without an order while orders of the batch wait to be assigned. */
    IDLE_ORDERS_WAITING("idle_orders_waiting"),

    /** Without an order and none waiting: the batch's tail, when the last orders are on their way. */
    IDLE_NOTHING_WAITING("idle_nothing_waiting"),
}

/**
 * Where the fleet's time goes, summed over vehicles, in simulated milliseconds: each vehicle is in one
 * [VehicleTimeUse] at a time, re-read at each event about it (and, for idle vehicles, when the batch's waiting orders
 * run out or come back). Work per event is constant but for that rare change. Kernel context.
 *
 * @param now the kernel clock in milliseconds.
 * @param timeFactor how much faster the vehicles run than the kernel clock.
 * @param order the kernel's current order of that name.
 * @param inBatch whether an order belongs to the simulated batch (not a park or recharge order).
 */
class VehicleTimeLedger(
    private val now: () -> Long,
    private val timeFactor: Double,
    private val order: (String) -> TransportOrder?,
    private val inBatch: (String) -> Boolean,
) {
    private val vehicles = HashMap<String, Vehicle>()
    private val uses = HashMap<String, VehicleTimeUse>()
    private val since = HashMap<String, Long>()
    private val totals = EnumMap<VehicleTimeUse, Double>(VehicleTimeUse::class.java)
    private val waiting = HashSet<String>()

    /** Starts counting with the fleet as it stands. */
    fun start(fleet: Collection<Vehicle>) {
        fleet.forEach {
            vehicles[it.name] = it
            reclassify(it.name)
        }
    }

    fun onEvent(event: KernelEvent) {
        when (event) {
            is VehicleEvent -> event.current?.let {
                vehicles[it.name] = it
                reclassify(it.name)
            }

            is TransportOrderEvent -> onOrder(event)

            else -> Unit
        }
    }

    /** Simulated milliseconds per use, summed over vehicles, up to now; the uses add up to vehicles × elapsed time. */
    fun totals(): Map<VehicleTimeUse, Double> {
        val at = now()
        val result = EnumMap<VehicleTimeUse, Double>(VehicleTimeUse::class.java)
        VehicleTimeUse.entries.forEach { result[it] = totals[it] ?: 0.0 }
        uses.forEach { (vehicle, use) -> result.merge(use, (at - since.getValue(vehicle)) * timeFactor, Double::plus) }
        return result
    }

    private fun onOrder(event: TransportOrderEvent) {
        val current = event.current ?: return
        if (inBatch(current.name)) {
            val wasWaiting = waiting.isNotEmpty()
            if (current.state == TransportOrderState.DISPATCHABLE) waiting += current.name else waiting -= current.name
            if (wasWaiting != waiting.isNotEmpty()) {
                vehicles.values.filter { it.transportOrder == null }.forEach {
                    reclassify(it.name)
                }
            }
        }
        current.processingVehicle?.let(::reclassify)
    }

    private fun reclassify(vehicle: String) {
        val state = vehicles[vehicle] ?: return
        val use = useOf(state)
        val before = uses[vehicle]
        if (before == use) return
        val at = now()
        before?.let { totals.merge(it, (at - since.getValue(vehicle)) * timeFactor, Double::plus) }
        uses[vehicle] = use
        since[vehicle] = at
    }

    private fun useOf(vehicle: Vehicle): VehicleTimeUse {
        val name = vehicle.transportOrder ?: return idle()
        if (!inBatch(name)) return VehicleTimeUse.PARKING
        val current = order(name) ?: return VehicleTimeUse.HELD_BACK
        if (vehicle.state != VehicleState.EXECUTING) return VehicleTimeUse.HELD_BACK
        val drive = current.currentDriveOrder ?: return VehicleTimeUse.HELD_BACK
        return when {
            vehicle.currentPosition == drive.route?.finalDestinationPoint -> VehicleTimeUse.OPERATING
            current.currentDriveOrderIndex == 0 -> VehicleTimeUse.DRIVING_EMPTY
            else -> VehicleTimeUse.DRIVING_LOADED
        }
    }

    private fun idle(): VehicleTimeUse =
        if (waiting.isEmpty()) VehicleTimeUse.IDLE_NOTHING_WAITING else VehicleTimeUse.IDLE_ORDERS_WAITING
}
