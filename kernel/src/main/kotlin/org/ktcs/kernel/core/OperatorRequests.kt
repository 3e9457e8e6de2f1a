package org.ktcs.kernel.core

import org.ktcs.api.error.IllegalStateChangeException
import org.ktcs.api.error.InvalidRequestException
import org.ktcs.api.model.EnergyLevelThresholdSet
import org.ktcs.api.order.TransportOrderState
import org.ktcs.kernel.dispatching.VehicleAvailability
import org.ktcs.kernel.orders.OrderLifecycle

/**
 * The rules of what an operator or a host may ask of the kernel directly, outside the dispatcher: each request checks
 * its preconditions and then changes the kernel state through [kernel]'s operations. Runs in the kernel context; the
 * services only hand the requests in.
 */
class OperatorRequests(private val kernel: KernelCore) {
    private val availability = VehicleAvailability(kernel.orders::get, kernel.sequences::get)

    /** Assigns the DISPATCHABLE [order] to its intended vehicle now, if that vehicle can take it, else says why not. */
    fun assignNow(order: String) {
        val current = kernel.orders.require(order)
        val vehicleName = current.intendedVehicle
            ?: throw IllegalStateChangeException("transport order '$order' has no intended vehicle to assign it to")
        if (current.state != TransportOrderState.DISPATCHABLE) {
            throw IllegalStateChangeException("transport order '$order' is ${current.state}, not DISPATCHABLE")
        }
        if (current.wrappingSequence != null) {
            throw IllegalStateChangeException("transport order '$order' belongs to a sequence")
        }
        val vehicle = kernel.plant.vehicle(vehicleName)
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
        val current = kernel.orders.require(order)
        if (current.state !in OrderLifecycle.UNASSIGNED) {
            throw IllegalStateChangeException(
                "transport order '$order' is ${current.state}; its intended vehicle can only change before it is assigned",
            )
        }
        vehicle?.let { kernel.plant.vehicle(it) }
        kernel.orders.update(order) { it.copy(intendedVehicle = vehicle) }
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
        kernel.plant.updateVehicle(vehicle) { it.copy(energyLevelThresholdSet = thresholds) }
    }

    /** Locks or unlocks [location]; the dispatcher then runs, since orders may have become possible or impossible. */
    fun setLocationLocked(location: String, locked: Boolean) {
        kernel.plant.setLocationLocked(location, locked)
        kernel.dispatch()
    }
}
