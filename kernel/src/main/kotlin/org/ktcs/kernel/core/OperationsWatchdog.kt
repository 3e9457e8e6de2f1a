package org.ktcs.kernel.core

import org.ktcs.api.event.NotificationLevel
import org.ktcs.api.kernel.Cancellable
import org.ktcs.api.model.PointType
import org.ktcs.api.model.Vehicle
import org.ktcs.api.model.VehicleState
import org.ktcs.api.order.TransportOrder
import org.ktcs.api.order.TransportOrderState
import org.ktcs.kernel.orders.waitingReason
import java.time.Duration
import java.time.Instant

/**
 * openTCS's watchdog checks, as user notifications, each said once per occurrence:
 * - a stranded vehicle: idle for [WatchdogOptions.strandedVehicleMillis] off a park position without an order, or
 *   idle while it holds an order;
 * - an order that waits unassigned (RAW, ACTIVE or DISPATCHABLE) for [WatchdogOptions.idleOrderMillis], with the
 *   dispatcher's reason, and an unfinished order past its deadline.
 * Positions off a vehicle's route are checked where they are reported ([org.ktcs.kernel.vehicles.VehicleController]).
 * Runs on the kernel clock, in the kernel context.
 */
class OperationsWatchdog(private val kernel: KernelCore, private val state: KernelState) {
    private val options = kernel.options.watchdog
    private val strandedSince = HashMap<String, Instant>()
    private val reportedVehicles = HashSet<String>()
    private val reportedWaiting = HashSet<String>()
    private val reportedLate = HashSet<String>()
    private val timers = mutableListOf<Cancellable>()

    fun start() {
        every(options.strandedVehicleCheckIntervalMillis, ::checkVehicles)
        every(options.orderCheckIntervalMillis, ::checkOrders)
    }

    fun stop() {
        timers.forEach { it.cancel() }
        timers.clear()
    }

    private fun every(interval: Long, check: () -> Unit) {
        if (interval <= 0) return
        timers += kernel.context.schedule(interval) {
            try {
                check()
            } finally {
                every(interval, check)
            }
        }
    }

    /** Finds vehicles stranded for longer than the threshold. */
    fun checkVehicles() {
        val now = kernel.context.now()
        val stranded = state.plant.vehicles().filter(::isStranded).mapTo(HashSet()) { it.name }
        strandedSince.keys.retainAll(stranded)
        reportedVehicles.retainAll(stranded)
        for (name in stranded) {
            val since = strandedSince.getOrPut(name) { now }
            if (Duration.between(since, now).toMillis() < options.strandedVehicleMillis) continue
            if (!reportedVehicles.add(name)) continue
            notify(name, "vehicle $name is stranded: ${strandedWhy(state.plant.vehicle(name))} since $since")
        }
    }

    /** Finds orders waiting longer than the threshold and unfinished orders past their deadline. */
    fun checkOrders() {
        val now = kernel.context.now()
        val open = state.orders.all().filter { !it.state.isFinal }
        val names = open.mapTo(HashSet()) { it.name }
        reportedWaiting.retainAll(names)
        reportedLate.retainAll(names)
        for (order in open) {
            if (isWaitingTooLong(order, now) && reportedWaiting.add(order.name)) {
                val why = order.waitingReason()?.let { ": $it" } ?: ""
                notify(order.name, "order ${order.name} has waited unassigned since ${order.creationTime}$why")
            }
            if (order.deadline < now && reportedLate.add(order.name)) {
                notify(order.name, "order ${order.name} is past its deadline ${order.deadline} (${order.state})")
            }
        }
    }

    private fun isWaitingTooLong(order: TransportOrder, now: Instant) = order.state in WAITING &&
        Duration.between(order.creationTime, now).toMillis() >= options.idleOrderMillis

    private fun isStranded(vehicle: Vehicle): Boolean {
        if (vehicle.state != VehicleState.IDLE || vehicle.currentPosition == null) return false
        return vehicle.transportOrder != null || !isParkPosition(vehicle.currentPosition!!)
    }

    private fun strandedWhy(vehicle: Vehicle): String = if (vehicle.transportOrder != null) {
        "idle at ${vehicle.currentPosition} while it holds order ${vehicle.transportOrder}"
    } else {
        "idle at ${vehicle.currentPosition}, which is no park position, without an order"
    }

    private fun isParkPosition(point: String) = state.plant.staticModel().point(point)?.type == PointType.PARK_POSITION

    private fun notify(source: String, text: String) = state.notifications.publish(
        source,
        NotificationLevel.NOTEWORTHY,
        text,
    )

    private companion object {
        val WAITING = setOf(TransportOrderState.RAW, TransportOrderState.ACTIVE, TransportOrderState.DISPATCHABLE)
    }
}
