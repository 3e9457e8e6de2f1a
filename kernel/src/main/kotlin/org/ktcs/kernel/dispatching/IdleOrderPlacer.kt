package org.ktcs.kernel.dispatching

import org.ktcs.api.error.KernelException
import org.ktcs.api.model.Vehicle
import org.ktcs.api.order.Destination
import org.ktcs.api.order.DriveOrder
import org.ktcs.api.order.Operations
import org.ktcs.api.order.TransportOrder
import org.ktcs.api.order.TransportOrderCreation
import org.ktcs.api.order.TransportOrderState
import org.slf4j.Logger
import org.slf4j.LoggerFactory

/**
 * Creates park and recharge orders for idle vehicles and assigns them at once. The order is routed and shown to the
 * driver as a draft first, because an order created but not assigned could not be taken back by the dispatcher and
 * would wait forever.
 */
internal class IdleOrderPlacer(private val run: DispatchRun) {
    fun park(vehicle: Vehicle, point: String): Boolean = place(
        vehicle,
        TransportOrderCreation(
            name = "Park-",
            destinations = listOf(Destination(point, Operations.PARK)),
            incompleteName = true,
            type = PARK_ORDER_TYPE,
            intendedVehicle = vehicle.name,
            dispensable = true,
        ),
    )

    /** Sends [vehicle] to [location]; routes avoid [avoid], e.g. the location's blocked access points. */
    fun recharge(vehicle: Vehicle, location: String, avoid: Set<String>): Boolean = place(
        vehicle,
        TransportOrderCreation(
            name = "Recharge-",
            destinations = listOf(Destination(location, vehicle.rechargeOperation)),
            incompleteName = true,
            type = CHARGE_ORDER_TYPE,
            intendedVehicle = vehicle.name,
            dispensable = !vehicle.isEnergyCritical,
            properties = avoidance(avoid),
        ),
    )

    private fun place(vehicle: Vehicle, creation: TransportOrderCreation): Boolean {
        val position = vehicle.currentPosition ?: return false
        val draft = draft(creation)
        val routed = run.context.router.routeOrder(vehicle, position, draft) ?: return false
        if (!run.context.driverAccepts(vehicle.name, draft).isYes) return false
        val order = create(creation) ?: return false
        val driveOrders = order.driveOrders.zip(routed) { created, draftRouted ->
            created.copy(route = draftRouted.route)
        }
        return run.assign(Candidate(vehicle, order, driveOrders))
    }

    private fun create(creation: TransportOrderCreation): TransportOrder? = try {
        run.context.createTransportOrder(creation)
    } catch (e: KernelException) {
        log.warn("Could not create {} order for {}: {}", creation.type, creation.intendedVehicle, e.message)
        null
    }

    private fun draft(creation: TransportOrderCreation) = TransportOrder(
        name = creation.name,
        driveOrders = creation.destinations.mapIndexed { index, destination ->
            DriveOrder("draft-$index", destination)
        },
        type = creation.type,
        state = TransportOrderState.DISPATCHABLE,
        creationTime = run.now,
        intendedVehicle = creation.intendedVehicle,
        dispensable = creation.dispensable,
        properties = creation.properties,
    )

    private fun avoidance(avoid: Set<String>): Map<String, String> =
        if (avoid.isEmpty()) {
            emptyMap()
        } else {
            mapOf(DispatcherProperties.RESOURCES_TO_AVOID to avoid.sorted().joinToString(","))
        }

    private companion object {
        val log: Logger = LoggerFactory.getLogger(DefaultDispatcher::class.java)
    }
}
