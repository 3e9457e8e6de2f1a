package org.ktcs.kernel.web.ws

import org.ktcs.api.event.KernelEvent
import org.ktcs.api.event.TransportOrderEvent
import org.ktcs.api.event.VehicleEvent
import org.ktcs.api.model.Vehicle
import org.ktcs.api.order.TransportOrder

/**
 * The top-level fields of an event's object whose values are not what they were before the event, for a client that
 * subscribed with `onlyChanged`: it keeps each object's latest state and merges what an event sends into it. A driving
 * vehicle then costs its name, its point and its pose per event instead of its whole state with a list of what was
 * left out, and an order advancing a step its name and its step index. Values are compared as the kernel holds them
 * (immutable, so most comparisons stop at the identity check), one reader per field of the wire object, so that no
 * field can be forgotten.
 */
internal object ChangedFields {
    /**
     * The wire names of the fields of [event]'s object that changed, but for `name` (always sent), or `null` where a
     * client gets the whole object: a new or removed object, or a topic whose objects go whole.
     */
    fun of(event: KernelEvent): List<String>? = when (event) {
        is VehicleEvent -> changed(event.previous, event.current, VehicleField.entries, ::valueOf) { it.wireName }
        is TransportOrderEvent -> changed(event.previous, event.current, OrderField.entries, ::valueOf) { it.wireName }
        else -> null
    }

    private fun <T : Any, F> changed(
        before: T?,
        after: T?,
        fields: List<F>,
        read: (F, T) -> Any?,
        wireName: (F) -> String,
    ): List<String>? {
        if (before == null || after == null) return null
        return fields.filter { read(it, before) != read(it, after) }.map(wireName)
    }

    // What the vehicle's [field] is written from; `name` is never reported as changed (events are matched by it).
    private fun valueOf(field: VehicleField, vehicle: Vehicle): Any? = when (field) {
        VehicleField.NAME, VehicleField.HISTORY -> null
        VehicleField.PROPERTIES -> vehicle.properties
        VehicleField.BOUNDING_BOX -> vehicle.boundingBox
        VehicleField.ENERGY_LEVEL_THRESHOLD_SET -> vehicle.energyLevelThresholdSet
        VehicleField.ENERGY_LEVEL -> vehicle.energyLevel
        VehicleField.MAX_VELOCITY -> vehicle.maxVelocity
        VehicleField.MAX_REVERSE_VELOCITY -> vehicle.maxReverseVelocity
        VehicleField.RECHARGE_OPERATION -> vehicle.rechargeOperation
        VehicleField.LOAD_HANDLING_DEVICES -> vehicle.loadHandlingDevices
        VehicleField.STATE -> vehicle.state to vehicle.stateTimestamp
        VehicleField.PROC_STATE -> vehicle.procState to vehicle.procStateTimestamp
        VehicleField.INTEGRATION_LEVEL -> vehicle.integrationLevel
        VehicleField.PAUSED -> vehicle.paused
        VehicleField.TRANSPORT_ORDER -> vehicle.transportOrder
        VehicleField.ORDER_SEQUENCE -> vehicle.orderSequence
        VehicleField.ACCEPTABLE_ORDER_TYPES -> vehicle.acceptableOrderTypes
        VehicleField.CLAIMED_RESOURCES -> vehicle.claimedResources
        VehicleField.ALLOCATED_RESOURCES -> vehicle.allocatedResources
        VehicleField.CURRENT_POSITION -> vehicle.currentPosition
        VehicleField.POSE -> vehicle.precisePosition to vehicle.orientationAngle
        VehicleField.ENVELOPE_KEY -> vehicle.envelopeKey
        VehicleField.LAYOUT -> vehicle.layout
        VehicleField.WAITING_REASON -> vehicle.waitingReason
    }

    // What the order's [field] is written from; its waiting reason is derived from its state and history, so it is
    // sent (as it is now) whenever one of those changed, without a scan of the history.
    private fun valueOf(field: OrderField, order: TransportOrder): Any? = when (field) {
        OrderField.NAME -> null
        OrderField.PROPERTIES -> order.properties
        OrderField.HISTORY -> order.history
        OrderField.TYPE -> order.type
        OrderField.DEPENDENCIES -> order.dependencies
        OrderField.DRIVE_ORDERS -> order.driveOrders
        OrderField.PERIPHERAL_RESERVATION_TOKEN -> order.peripheralReservationToken
        OrderField.CURRENT_DRIVE_ORDER_INDEX -> order.currentDriveOrderIndex
        OrderField.CURRENT_ROUTE_STEP_INDEX -> order.currentRouteStepIndex
        OrderField.STATE -> order.state
        OrderField.CREATION_TIME -> order.creationTime
        OrderField.DEADLINE -> order.deadline
        OrderField.FINISHED_TIME -> order.finishedTime
        OrderField.INTENDED_VEHICLE -> order.intendedVehicle
        OrderField.PROCESSING_VEHICLE -> order.processingVehicle
        OrderField.WRAPPING_SEQUENCE -> order.wrappingSequence
        OrderField.DISPENSABLE -> order.dispensable
        OrderField.WAITING_REASON -> order.state to order.history
    }
}
