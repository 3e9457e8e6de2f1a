package org.ktcs.api.driver

/**
 * A base for drivers: keeps the commands sent to the vehicle within [commandQueueCapacity] and the enabled state.
 * Subclasses send a command in [sendCommand] and call [onCommandExecuted] / [onCommandFailed] (in the kernel
 * context, e.g. through `context.clock.schedule(0) { … }`) when the vehicle reports back.
 */
public abstract class BasicVehicleDriver(
    override val vehicleName: String,
    protected val context: DriverContext,
    override val commandQueueCapacity: Int = 2,
    override val rechargeOperation: String = "CHARGE",
) : VehicleDriver {
    private val sent = ArrayDeque<MovementCommand>()
    private var enabled = false

    override val isEnabled: Boolean get() = enabled

    override val pendingCommands: List<MovementCommand> get() = sent.toList()

    override fun enable() {
        if (enabled) return
        enabled = true
        onEnabled()
    }

    override fun disable() {
        if (!enabled) return
        enabled = false
        sent.clear()
        onDisabled()
    }

    override fun canAcceptNextCommand(): Boolean = enabled && sent.size < commandQueueCapacity

    override fun enqueueCommand(command: MovementCommand): Boolean {
        if (!canAcceptNextCommand()) return false
        sent.addLast(command)
        sendCommand(command)
        return true
    }

    override fun clearCommandQueue() {
        sent.clear()
        onCommandQueueCleared()
    }

    /** Sends [command] to the vehicle. */
    protected abstract fun sendCommand(command: MovementCommand)

    /** Called when the driver is enabled. */
    protected open fun onEnabled() {}

    /** Called when the driver is disabled. */
    protected open fun onDisabled() {}

    /** Called after the pending commands were dropped. */
    protected open fun onCommandQueueCleared() {}

    /** The vehicle carried out [command]; ignored if it is no longer pending (e.g. the queue was cleared). */
    protected fun onCommandExecuted(command: MovementCommand) {
        if (sent.remove(command)) context.commandExecuted(command)
    }

    /** The vehicle failed to carry out [command]; ignored if it is no longer pending. */
    protected fun onCommandFailed(command: MovementCommand) {
        if (sent.remove(command)) context.commandFailed(command)
    }

    /** The vehicle failed to carry out [command] for [reason] (goes into the order's history); ignored if not pending. */
    protected fun onCommandFailed(command: MovementCommand, reason: String) {
        if (sent.remove(command)) context.commandFailed(command, reason)
    }
}
