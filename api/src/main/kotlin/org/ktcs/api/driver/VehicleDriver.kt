package org.ktcs.api.driver

import org.ktcs.api.kernel.Explained
import org.ktcs.api.order.TransportOrder

/**
 * Talks to one vehicle: sends it movement commands and reports what it does through its [DriverContext].
 *
 * The kernel calls these methods in the kernel context. A driver that receives data on its own threads (network
 * I/O) passes it to the context, which is safe to call from any thread.
 */
public interface VehicleDriver {
    /** The vehicle this driver talks to. */
    public val vehicleName: String

    /** Whether the driver is enabled: only an enabled driver gets commands. */
    public val isEnabled: Boolean

    /** How many commands the vehicle can hold at a time. */
    public val commandQueueCapacity: Int

    /** The operation that recharges this vehicle. */
    public val rechargeOperation: String

    /** Starts communicating with the vehicle. */
    public fun enable()

    /** Stops communicating with the vehicle; pending commands are dropped. */
    public fun disable()

    /** Whether the vehicle can take one more command now. */
    public fun canAcceptNextCommand(): Boolean

    /** Sends [command] to the vehicle; returns `false` (and does nothing) if it cannot take it now. */
    public fun enqueueCommand(command: MovementCommand): Boolean

    /** Drops every command the vehicle has not finished yet, e.g. when its order is withdrawn immediately. */
    public fun clearCommandQueue()

    /** The commands sent and not yet reported executed or failed, oldest first. */
    public val pendingCommands: List<MovementCommand>

    /** Whether the vehicle can carry out [order]; a "no" with reasons vetoes the assignment. */
    public fun canProcess(order: TransportOrder): Explained = Explained.YES

    /** Handles a message from a client; unknown message types are ignored. */
    public fun processMessage(message: DriverMessage) {}

    /** The vehicle was paused or resumed. */
    public fun onPaused(paused: Boolean) {}

    /**
     * What the driver's [DriverPanel] shows besides the kernel's view of the vehicle, e.g. `singleStepMode=true`;
     * called in the kernel context whenever a client asks.
     */
    public fun panelState(): Map<String, String> = emptyMap()
}

/**
 * Creates drivers; found at start-up through [java.util.ServiceLoader] (list the class in
 * `META-INF/services/org.ktcs.api.driver.VehicleDriverFactory`) or contributed by an extension.
 */
public interface VehicleDriverFactory {
    /** A short unique name, used in the vehicle property `tcs:preferredAdapterClass` and the web API. */
    public val name: String

    /** A human-readable description. */
    public val description: String

    /** Whether this factory can create a driver for the vehicle named [vehicleName] in the current model. */
    public fun canDrive(vehicleName: String, context: DriverContext): Boolean = true

    /**
     * Whether this factory should drive the vehicle named [vehicleName] when its `tcs:preferredAdapterClass` names no
     * available driver, e.g. because the vehicle's own properties say what it speaks (`vda5050:version`). The first
     * factory that claims a vehicle wins over the first one that merely can drive it.
     */
    public fun claims(vehicleName: String, context: DriverContext): Boolean = false

    /** Creates a driver for the vehicle named [vehicleName]; it starts disabled. */
    public fun create(vehicleName: String, context: DriverContext): VehicleDriver

    /** The panel the overview shows for the vehicles this factory's drivers drive, `null` for none. */
    public val panel: DriverPanel? get() = null
}
