package org.ktcs.kernel.core

import org.ktcs.api.error.IllegalStateChangeException
import org.ktcs.api.error.InvalidRequestException
import org.ktcs.api.event.NotificationLevel
import org.ktcs.api.model.PlantModel
import org.ktcs.api.model.VehicleState
import org.ktcs.kernel.validation.InvalidModelException
import org.ktcs.kernel.validation.PlantModelValidator
import org.ktcs.kernel.workingset.TopologyChange

/** Changes of the plant itself (path locks, a new model, a changed topology), with their rules. Kernel context. */
internal class PlantChanges(
    private val kernel: KernelCore,
    private val state: KernelState,
    private val dispatchable: DispatchableOrders,
) {
    private val router get() = kernel.router

    /** See [KernelCore.setPathLocked]. */
    fun setPathLocked(path: String, locked: Boolean) {
        state.plant.setPathLocked(path, locked)
        router.updateTopology(state.plant.layoutWithLocks())
        if (locked) rerouteAround(path)
        kernel.dispatch()
    }

    /** See [KernelCore.replacePlantModel]. */
    fun replace(model: PlantModel, persist: (PlantModel) -> Unit) {
        val topologyChange = TopologyChange.between(state.plant.model(), model)
        if (topologyChange == null) refuseWhileBusy()
        try {
            PlantModelValidator.requireValid(model)
        } catch (error: InvalidModelException) {
            throw InvalidRequestException(error.message!!.lines().joinToString(" ") { it.trim() })
        }
        persist(model)
        if (topologyChange != null) return applyTopologyChange(topologyChange)
        state.controllers.discard()
        state.orders.removeFinal()
        state.sequences.removeFinished()
        dispatchable.clear()
        state.plant.replace(model)
        router.updateTopology(state.plant.layoutWithLocks())
        kernel.scheduler.updatePlantModel(state.plant.layoutWithLocks())
        state.controllers.start(kernel.options.enableDriversOnStart, kernel.options.initialIntegrationLevel)
        announceTrafficLimits()
        kernel.dispatch()
    }

    /** Where the plant itself defeats deadlock avoidance (dead ends with several stops), operators hear it at once. */
    fun announceTrafficLimits() {
        PlantModelValidator.trafficWarnings(state.plant.layoutWithLocks()).forEach {
            state.notifications.publish("traffic control", NotificationLevel.IMPORTANT, "${it.element}: ${it.message}")
        }
    }

    private fun applyTopologyChange(change: TopologyChange) {
        val running = state.plant.model()
        state.plant.apply(change)
        router.updateTopology(state.plant.layoutWithLocks())
        change.paths.filter { it.locked && running.path(it.name)?.locked == false }.forEach { rerouteAround(it.name) }
        kernel.dispatch()
    }

    private fun rerouteAround(path: String) {
        state.plant.vehicles().filter { vehicle -> vehicle.claimedResources.any { path in it } }.forEach { vehicle ->
            if (!kernel.reroute(vehicle.name, avoid = emptySet())) {
                state.notifications.publish(
                    vehicle.name,
                    NotificationLevel.NOTEWORTHY,
                    "vehicle ${vehicle.name} has no way around locked path $path and keeps its route",
                )
            }
        }
    }

    private fun refuseWhileBusy() {
        val busyOrders = state.orders.all().filterNot { it.state.isFinal }.map { it.name }
        val openSequences = state.sequences.all().filterNot { it.finished }.map { it.name }
        // An order withdrawn immediately is final at once, while its vehicle may still be finishing a movement.
        val moving = state.plant.vehicles().filter { it.state == VehicleState.EXECUTING }.map { it.name }
        if (busyOrders.isEmpty() && openSequences.isEmpty() && moving.isEmpty()) return
        val reasons = listOfNotNull(
            busyOrders.takeIf { it.isNotEmpty() }?.let { "${it.size} transport order(s) not final (${it.sample()})" },
            openSequences.takeIf {
                it.isNotEmpty()
            }?.let { "${it.size} order sequence(s) not finished (${it.sample()})" },
            moving.takeIf { it.isNotEmpty() }?.let { "${it.size} vehicle(s) still moving (${it.sample()})" },
        )
        throw IllegalStateChangeException(
            "the plant model cannot be replaced while orders are being processed: ${reasons.joinToString("; ")}; " +
                "withdraw them or wait until they are done",
        )
    }

    private fun List<String>.sample(): String = take(SAMPLE_SIZE).joinToString() + if (size > SAMPLE_SIZE) ", …" else ""

    private companion object {
        const val SAMPLE_SIZE = 5
    }
}
