package org.ktcs.api.driver

import org.ktcs.api.event.NotificationLevel
import org.ktcs.api.kernel.KernelClock
import org.ktcs.api.model.LoadHandlingDevice
import org.ktcs.api.model.PlantModel
import org.ktcs.api.model.Position
import org.ktcs.api.model.Vehicle
import org.ktcs.api.model.VehicleState

/**
 * What a driver can see of the kernel and how it reports its vehicle. Every method may be called from any thread:
 * the reads return immutable values the kernel publishes, and the kernel applies the reports in its own context, in
 * the order they were made.
 */
public interface DriverContext {
    /** The kernel's clock; simulated drivers schedule their work on it so they follow virtual time too. */
    public val clock: KernelClock

    /** The plant with its current locks; its vehicles are as loaded (use [vehicle] for the driver's own). */
    public val plantModel: PlantModel

    /** The vehicle as the kernel knows it now. */
    public fun vehicle(): Vehicle

    /** The points the kernel's vehicles stand on now, by vehicle name; vehicles without a known position are left out. */
    public fun vehiclePositions(): Map<String, String>

    /** The vehicle reached the point named [point] (`null`: its position is unknown). */
    public fun reportPosition(point: String?)

    /** The vehicle's exact position and orientation (degrees), e.g. while it is between points. */
    public fun reportPrecisePosition(position: Position?, orientationAngle: Double)

    /** The vehicle's state changed. */
    public fun reportState(state: VehicleState)

    /** The vehicle's energy level, in percent. */
    public fun reportEnergyLevel(percent: Int)

    /** The vehicle's load handling devices changed. */
    public fun reportLoadHandlingDevices(devices: List<LoadHandlingDevice>)

    /** The vehicle carried out [command]. */
    public fun commandExecuted(command: MovementCommand)

    /** The vehicle could not carry out [command]; the kernel withdraws its order. */
    public fun commandFailed(command: MovementCommand)

    /**
     * The vehicle could not carry out [command] for [reason], in the vehicle's words (e.g. the error type and
     * description it reported): the kernel withdraws its order and writes [reason] into the order's history and the
     * operator's notification. A context that keeps no history treats it as [commandFailed] without a reason.
     */
    public fun commandFailed(command: MovementCommand, reason: String): Unit = commandFailed(command)

    /**
     * The vehicle's length in mm changed, e.g. with its load (openTCS's `vda5050:vehicleLengthLoaded`): the
     * scheduler's length-respecting release of passed resources (`scheduler.resourceManagement=LENGTH_RESPECTED`)
     * uses it from the next step on.
     */
    public fun reportLength(length: Long)

    /** Sets ([value] non-null) or removes a property of the vehicle. */
    public fun setVehicleProperty(key: String, value: String?)

    /** Sets ([value] non-null) or removes a property of the vehicle's current transport order. */
    public fun setTransportOrderProperty(key: String, value: String?)

    /**
     * Publishes a driver-specific event ([org.ktcs.api.event.DriverEvent]) to the kernel's event stream, which the web
     * API passes on to clients (WebSocket topic `driverEvents`, SSE) and the vehicle's driver panel shows.
     */
    public fun publishEvent(type: String, payload: Map<String, String> = emptyMap())

    /** Tells the operators something. */
    public fun notifyUser(level: NotificationLevel, text: String)
}
