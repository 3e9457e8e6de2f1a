package org.ktcs.api.driver

import org.ktcs.api.order.Step

/**
 * One step of a route that the kernel sends to a vehicle: drive [step], then perform [operation] at [opLocation]
 * if there is one.
 *
 * @property finalMovement whether this is the last step of the drive order.
 * @property finalDestination the point the drive order ends at.
 * @property finalDestinationLocation the location the drive order ends at, if it ends at one.
 * @property finalOperation the operation at the end of the drive order.
 * @property properties the transport order's and the destination's properties, the destination's winning.
 */
public data class MovementCommand(
    val transportOrder: String,
    val driveOrder: String,
    val step: Step,
    val operation: String,
    val opLocation: String?,
    val finalMovement: Boolean,
    val finalDestination: String,
    val finalDestinationLocation: String?,
    val finalOperation: String,
    val properties: Map<String, String> = emptyMap(),
) {
    /** Whether the vehicle has something to do after driving the step. */
    val hasOperation: Boolean get() = opLocation != null && operation.isNotEmpty() && operation != NO_OPERATION

    public companion object {
        /** The operation that does nothing. */
        public const val NO_OPERATION: String = "NOP"
    }
}

/**
 * A message to a driver from a client (web API, overview, another extension), e.g.
 * `tcs:virtualVehicle:setEnergyLevel` with parameter `value=40` for the loopback vehicle.
 */
public data class DriverMessage(val type: String, val parameters: Map<String, String> = emptyMap())
