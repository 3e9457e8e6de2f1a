package org.ktcs.kernel.core

import org.ktcs.api.model.BlockType
import org.ktcs.api.order.TransportOrderState
import org.ktcs.api.scheduling.Scheduler

/**
 * Where a fact is published in more than one immutable value, whether the copies agree once a step is done:
 * - which vehicle does which order: the vehicle's `transportOrder` (its controller reads it there) and the order's
 *   `processingVehicle`;
 * - which resources a vehicle holds: its controller's (the store), the vehicle's `allocatedResources` (published
 *   from it) and the scheduler's allocations (the same, with the rest of any SINGLE_VEHICLE_ONLY block they touch).
 * Tests check after every step of random operations that they never disagree.
 */
internal class StateAgreement(private val state: KernelState, private val scheduler: () -> Scheduler) {
    /** Every disagreement between the copies, as text; empty when they all agree. */
    fun disagreements(): List<String> = orderAssignments() + heldResources()

    private fun orderAssignments(): List<String> {
        val found = mutableListOf<String>()
        state.plant.vehicles().forEach { vehicle ->
            val name = vehicle.transportOrder ?: return@forEach
            val order = state.orders.get(name)
            if (order == null) {
                found += "vehicle ${vehicle.name} shows order $name, which the kernel does not know"
                return@forEach
            }
            if (order.processingVehicle != vehicle.name) {
                found += "vehicle ${vehicle.name} shows order ${order.name}, which names ${order.processingVehicle}"
            }
            if (order.state.isFinal) {
                found += "vehicle ${vehicle.name} shows order ${order.name}, which is ${order.state}"
            }
        }
        state.orders.all().filter { it.state in UNDER_WAY && it.processingVehicle != null }.forEach { order ->
            val shown = state.plant.vehicleOrNull(order.processingVehicle!!)?.transportOrder
            if (shown != order.name) {
                found += "order ${order.name} names vehicle ${order.processingVehicle}, which shows $shown"
            }
        }
        return found
    }

    // The scheduler takes a SINGLE_VEHICLE_ONLY block as a whole, so it may hold more: the rest of such blocks.
    private fun heldResources(): List<String> {
        val allocations = scheduler().allocations()
        val singleBlocks = state.plant.staticModel().blocks.filter { it.type == BlockType.SINGLE_VEHICLE_ONLY }
        return state.plant.vehicles().mapNotNull { vehicle ->
            val scheduled = allocations[vehicle.name].orEmpty()
            val controllers = state.controllers.controller(vehicle.name).held.all()
            val shown = vehicle.allocatedResources.flatMapTo(HashSet()) { it }
            val blocks = singleBlocks.filter { block -> block.members.any { it in controllers } }
            val expanded = blocks.flatMapTo(HashSet(controllers)) { it.members }
            if (controllers == shown && scheduled.containsAll(controllers) && expanded.containsAll(scheduled)) {
                return@mapNotNull null
            }
            "vehicle ${vehicle.name} holds ${shown.sorted()}, its controller ${controllers.sorted()}, " +
                "the scheduler ${scheduled.sorted()}"
        }
    }

    private companion object {
        val UNDER_WAY = setOf(TransportOrderState.BEING_PROCESSED)
    }
}
