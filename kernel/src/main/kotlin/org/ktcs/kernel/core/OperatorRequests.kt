package org.ktcs.kernel.core

import org.ktcs.api.driver.DriverMessage
import org.ktcs.api.driver.DriverPanelView
import org.ktcs.api.error.IllegalStateChangeException
import org.ktcs.api.error.InvalidRequestException
import org.ktcs.api.error.ObjectUnknownException
import org.ktcs.api.model.EnergyLevelThresholdSet
import org.ktcs.api.model.IntegrationLevel
import org.ktcs.api.model.Vehicle
import org.ktcs.api.order.Route
import org.ktcs.api.order.TransportOrderState
import org.ktcs.kernel.dispatching.VehicleAvailability
import org.ktcs.kernel.orders.OrderLifecycle
import org.ktcs.kernel.vehicles.DriverPanels

/**
 * The rules of what an operator or a host may ask of the kernel directly, outside the dispatcher: each request checks
 * its preconditions and then changes the kernel state through [kernel]'s operations. Runs in the kernel context; the
 * services only hand the requests in.
 */
class OperatorRequests(private val kernel: KernelCore, private val state: KernelState) {
    private val availability = VehicleAvailability(state.orders::get, state.sequences::get)
    private val panels = DriverPanels(state.controllers) { state.plant.staticModel() }

    /** Assigns the DISPATCHABLE [order] to its intended vehicle now, if that vehicle can take it, else says why not. */
    fun assignNow(order: String) {
        val current = state.orders.require(order)
        val vehicleName = current.intendedVehicle
            ?: throw IllegalStateChangeException("transport order '$order' has no intended vehicle to assign it to")
        if (current.state != TransportOrderState.DISPATCHABLE) {
            throw IllegalStateChangeException("transport order '$order' is ${current.state}, not DISPATCHABLE")
        }
        if (current.wrappingSequence != null) {
            throw IllegalStateChangeException("transport order '$order' belongs to a sequence")
        }
        val vehicle = state.plant.vehicle(vehicleName)
        val work = VehicleAvailability.Work(orderType = current.type, mayReplaceDispensable = false)
        val refusals = availability.reasons(vehicle, work)
        if (refusals.isNotEmpty()) {
            throw IllegalStateChangeException(
                "cannot assign '$order' to vehicle '$vehicleName' now: ${refusals.joinToString(", ")}",
            )
        }
        val driveOrders = kernel.router.routeOrder(vehicle, vehicle.currentPosition!!, current)
            ?: throw IllegalStateChangeException("no route for vehicle '$vehicleName' to carry out '$order'")
        kernel.assign(order, vehicleName, driveOrders)
    }

    /** Sets or clears the vehicle [order] is meant for; only before it is assigned. */
    fun setIntendedVehicle(order: String, vehicle: String?) {
        val current = state.orders.require(order)
        if (current.state !in OrderLifecycle.UNASSIGNED) {
            throw IllegalStateChangeException(
                "transport order '$order' is ${current.state}; its intended vehicle can only change before it is assigned",
            )
        }
        vehicle?.let { state.plant.vehicle(it) }
        state.orders.update(order) { it.copy(intendedVehicle = vehicle) }
        kernel.dispatch()
    }

    /** Sets [vehicle]'s energy thresholds: percentages, critical not above good, sufficiently not above fully. */
    fun setEnergyLevelThresholds(vehicle: String, thresholds: EnergyLevelThresholdSet) {
        val values =
            listOf(thresholds.critical, thresholds.good, thresholds.sufficientlyRecharged, thresholds.fullyRecharged)
        if (values.any { it !in 0..100 }) {
            throw InvalidRequestException(
                "energy thresholds of vehicle '$vehicle' must be between 0 and 100: $thresholds",
            )
        }
        if (thresholds.critical > thresholds.good) {
            throw InvalidRequestException(
                "vehicle '$vehicle': critical ${thresholds.critical} is above good ${thresholds.good}",
            )
        }
        if (thresholds.sufficientlyRecharged > thresholds.fullyRecharged) {
            throw InvalidRequestException(
                "vehicle '$vehicle': sufficiently recharged ${thresholds.sufficientlyRecharged} is above fully " +
                    "recharged ${thresholds.fullyRecharged}",
            )
        }
        state.plant.updateVehicle(vehicle) { it.copy(energyLevelThresholdSet = thresholds) }
    }

    /** Locks or unlocks [location]; the dispatcher then runs, since orders may have become possible or impossible. */
    fun setLocationLocked(location: String, locked: Boolean) {
        state.plant.setLocationLocked(location, locked)
        kernel.dispatch()
    }

    /** Changes settings of [vehicle] that need no other check (order types, envelope key); the dispatcher then runs. */
    fun updateVehicle(vehicle: String, change: (Vehicle) -> Vehicle) {
        state.plant.updateVehicle(vehicle, change)
        kernel.dispatch()
    }

    fun setIntegrationLevel(vehicle: String, level: IntegrationLevel) = state.controllers.setIntegrationLevel(
        vehicle,
        level,
    )

    fun setPaused(vehicle: String, paused: Boolean) = state.controllers.setPaused(vehicle, paused)

    fun attachDriver(vehicle: String, driver: String) = state.controllers.attach(vehicle, driver)

    fun setDriverEnabled(vehicle: String, enabled: Boolean) = state.controllers.setDriverEnabled(vehicle, enabled)

    fun sendDriverMessage(vehicle: String, message: DriverMessage) = state.controllers.sendMessage(vehicle, message)

    fun driverPanel(vehicle: String): DriverPanelView = panels.view(vehicle)

    fun executeDriverCommand(vehicle: String, driver: String, command: String, parameters: Map<String, String>) =
        panels.execute(vehicle, driver, command, parameters)

    /** Withdraws [vehicle]'s order, if it has one; [disableVehicle] sets it to TO_BE_RESPECTED in any case. */
    fun withdrawByVehicle(vehicle: String, immediate: Boolean, disableVehicle: Boolean) {
        val order = state.plant.vehicle(vehicle).transportOrder
        if (order != null) {
            kernel.withdraw(order, immediate, disableVehicle)
        } else if (disableVehicle) {
            state.controllers.setIntegrationLevel(vehicle, IntegrationLevel.TO_BE_RESPECTED)
        }
    }

    /** Routes [vehicle] again; a [forced] reroute starts from where it stands, also off its route; else says why not. */
    fun reroute(vehicle: String, forced: Boolean) {
        state.plant.vehicle(vehicle)
        state.controllers.controller(vehicle).reroute(emptySet(), forced)?.let {
            throw IllegalStateChangeException("cannot reroute vehicle '$vehicle': $it")
        }
    }

    /**
     * Up to [maxRoutes] routes for [vehicle] from [sourcePoint] (its position when null) to each of
     * [destinationPoints], around [resourcesToAvoid].
     */
    fun routes(
        vehicle: String,
        sourcePoint: String?,
        destinationPoints: List<String>,
        resourcesToAvoid: Set<String>,
        maxRoutes: Int,
    ): Map<String, List<Route>> {
        val current = state.plant.vehicle(vehicle)
        val source = sourcePoint ?: current.currentPosition
            ?: throw InvalidRequestException("vehicle '$vehicle' has no known position; give a source point")
        (destinationPoints + source).forEach { point ->
            state.plant.staticModel().point(point) ?: throw ObjectUnknownException("unknown point '$point'")
        }
        return destinationPoints.associateWith {
            kernel.router.routes(current, source, it, resourcesToAvoid, maxRoutes)
        }
    }
}
