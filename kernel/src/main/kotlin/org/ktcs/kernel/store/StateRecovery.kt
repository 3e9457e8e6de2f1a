package org.ktcs.kernel.store

import org.ktcs.api.error.KernelException
import org.ktcs.api.event.NotificationLevel
import org.ktcs.api.model.IntegrationLevel
import org.ktcs.api.order.DriveOrderState
import org.ktcs.api.order.TransportOrder
import org.ktcs.api.order.TransportOrderState
import org.ktcs.kernel.config.RecoveryMode
import org.ktcs.kernel.core.KernelCore
import org.slf4j.LoggerFactory

/**
 * Puts the state of a previous run back into the kernel, in the kernel context: [restore] before the kernel starts
 * (objects as they were, without events), [resume] right after it started (vehicles' settings, then the orders
 * that were under way continued or withdrawn, as `persistence.recovery` says).
 */
class StateRecovery(private val core: KernelCore, private val state: StoredState, private val mode: RecoveryMode) {
    private val log = LoggerFactory.getLogger(StateRecovery::class.java)
    private val restoration = core.restoration
    private val ignored = mutableListOf<String>()

    fun restore() {
        state.names?.let { restoration.names(it.millis, it.counter) }
        state.sequences.forEach(restoration::sequence)
        state.orders.forEach(restoration::order)
        restoration.notifications(state.notifications.map { it.second })
        state.locks.forEach { (name, lock) -> restoreLock(name, lock) }
        state.vehicles.forEach { stored ->
            if (core.plant.vehicleOrNull(stored.name) == null) {
                ignored += "vehicle ${stored.name}"
            } else {
                restoration.vehicle(stored.name) { stored.applyTo(it) }
            }
        }
    }

    /** Continues what was under way; returns the summary it also logs and announces. */
    fun resume(): String {
        state.vehicles.filter { core.plant.vehicleOrNull(it.name) != null }.forEach(::resumeVehicle)
        var continued = 0
        var withdrawn = 0
        state.orders.forEach { stored ->
            val order = core.orders.get(stored.name) ?: return@forEach
            when (order.state) {
                TransportOrderState.BEING_PROCESSED -> {
                    val reason = if (mode == RecoveryMode.CONTINUE) {
                        continueOrder(
                            order,
                        )
                    } else {
                        "persistence.recovery=WITHDRAW"
                    }
                    if (reason == null) continued++ else withdraw(order, reason).also { withdrawn++ }
                }

                TransportOrderState.WITHDRAWN -> withdraw(order, "it was being withdrawn")

                else -> restoration.settled(order)
            }
        }
        state.sequences.filter { !it.finished && it.processingVehicle != null }.forEach { sequence ->
            core.plant.vehicleOrNull(sequence.processingVehicle!!)?.let {
                restoration.sequenceOf(it.name, sequence.name)
            }
        }
        core.dispatch()
        val open = state.orders.count { !it.state.isFinal }
        val summary = "state recovered: ${state.orders.size} transport order(s) ($open not final: $continued " +
            "continued, $withdrawn withdrawn, the others dispatched again), ${state.sequences.size} order " +
            "sequence(s), ${state.vehicles.size} vehicle(s), ${state.locks.count { it.value.locked }} lock(s)" +
            if (ignored.isEmpty()) "" else "; not in the plant model and ignored: ${ignored.joinToString()}"
        log.info(summary)
        if (!state.isEmpty) core.publishNotification("kernel", NotificationLevel.NOTEWORTHY, summary)
        return summary
    }

    private fun restoreLock(name: String, lock: StoredLock) {
        try {
            if (lock.kind == StoredLock.PATH) {
                restoration.pathLock(name, lock.locked)
            } else {
                restoration.locationLock(name, lock.locked)
            }
        } catch (unknown: KernelException) {
            ignored += "${lock.kind} $name"
        }
    }

    private fun resumeVehicle(stored: StoredVehicle) {
        val controllers = core.controllers
        val requests = core.requests
        try {
            val driver = stored.driver
            if (driver != null && driver != controllers.driverName(
                    stored.name,
                ) && controllers.factory(driver) != null
            ) {
                requests.attachDriver(stored.name, driver)
                if (core.options.enableDriversOnStart) requests.setDriverEnabled(stored.name, true)
            }
            requests.setIntegrationLevel(stored.name, stored.integrationLevel)
            if (stored.paused) requests.setPaused(stored.name, true)
        } catch (refused: KernelException) {
            log.warn("vehicle {}: its stored settings are not all restored: {}", stored.name, refused.message)
        }
    }

    /** Reroutes [order]'s vehicle from its last known position to the remaining destinations; null or why not. */
    private fun continueOrder(order: TransportOrder): String? {
        val vehicle = order.processingVehicle?.let(core.plant::vehicleOrNull) ?: return "its vehicle is unknown"
        val position = vehicle.currentPosition ?: return "the position of vehicle ${vehicle.name} is unknown"
        if (vehicle.integrationLevel < IntegrationLevel.TO_BE_RESPECTED) {
            return "vehicle ${vehicle.name} is ${vehicle.integrationLevel}"
        }
        if (restoration.busyWith(vehicle.name) != null) return "vehicle ${vehicle.name} is busy"
        val index = order.driveOrders.indexOfFirst { it.state != DriveOrderState.FINISHED }
        if (index < 0) return "all its drive orders were finished"
        val rest = order.driveOrders.drop(index).map { it.copy(route = null, state = DriveOrderState.PRISTINE) }
        val routed = core.router.routeOrder(vehicle, position, order.copy(driveOrders = rest))
            ?: return "no route leads from $position to its remaining destinations"
        restoration.continueOrder(order, index, routed, KERNEL_RESTARTED, "continued from $position")
        return null
    }

    private fun withdraw(order: TransportOrder, reason: String) {
        restoration.failOrder(order, KERNEL_RESTARTED, "withdrawn: $reason", "withdrawn: the kernel restarted")
    }

    companion object {
        /** History code of an order that was under way when the kernel stopped. */
        const val KERNEL_RESTARTED = "ktcs:history:kernelRestarted"
    }
}
