package org.ktcs.adapters.loopback

import org.ktcs.api.driver.DriverContext
import org.ktcs.api.driver.MovementCommand
import org.ktcs.api.event.NotificationLevel
import org.ktcs.api.model.VehicleState
import kotlin.math.roundToLong

/**
 * Carries out a loopback vehicle's commands one at a time, oldest first: drive the step, then perform the operation.
 * Confined to the kernel context, like its driver.
 */
internal class Simulation(
    private val context: DriverContext,
    private val settings: LoopbackSettings,
    private val vehicle: VirtualVehicle,
    private val queue: CommandQueue,
) {
    private val time = SimulatedTime(context.clock, settings.timeFactor)
    private val charger = Charger(time, vehicle.battery, settings.rechargePercentPerSecond, ::fullyCharged)
    private val drain = Drain(vehicle.battery, settings.energyDrainPercentPerKm)
    private var activity: Activity? = null
    private var velocity = 0.0

    /** Set when the battery ran empty while driving; the vehicle stays put until it gets energy again. */
    private var stranded = false

    private var paused = false
    var singleStepMode: Boolean = false
        private set

    fun parameters(): VehicleParameters = VehicleParameters.of(context.vehicle(), settings)

    fun commandAdded() {
        val driving = activity as? Driving
        if (driving != null && mayKeepGoing(driving.command)) driving.keepGoing()
        if (activity == null && !singleStepMode) startNext()
    }

    fun pause(paused: Boolean) {
        this.paused = paused
        if (paused) activity?.pause() else activity?.resume()
    }

    val timeFactor: Double get() = time.timeFactor

    val isPaused: Boolean get() = paused

    /** In single-step mode: whether a command waits for the next step. */
    fun isWaitingForStep(): Boolean = singleStepMode && activity == null && queue.pending.isNotEmpty()

    /** Simulated time runs [factor] times faster from now on; what the vehicle is doing carries on at the new pace. */
    fun setTimeFactor(factor: Double) {
        activity?.pause()
        val charging = charger.isCharging
        charger.stop()
        time.changeFactor(factor)
        if (charging) charger.start()
        if (!paused) activity?.resume()
        context.publishEvent(LoopbackEvents.TIME_FACTOR_CHANGED, mapOf("timeFactor" to factor.toString()))
    }

    fun setSingleStepMode(enabled: Boolean) {
        singleStepMode = enabled
        context.publishEvent(LoopbackEvents.SINGLE_STEP_MODE_CHANGED, mapOf("enabled" to enabled.toString()))
        if (!enabled && activity == null && queue.pending.isNotEmpty()) startNext()
    }

    fun triggerSingleStep() {
        if (singleStepMode && activity == null && queue.pending.isNotEmpty()) startNext()
    }

    /** Stops everything, e.g. when the driver is disabled or enabled again. */
    fun reset() {
        halt()
        charger.stop()
        stranded = false
    }

    /** The kernel dropped the pending commands: stop where the vehicle is. */
    fun commandsDropped() {
        halt()
        rest()
    }

    /** Reports the oldest pending command failed and goes on with the next; `false` if there is none. */
    fun failCurrentCommand(): Boolean {
        val command = queue.pending.firstOrNull() ?: return false
        halt()
        LoopbackEvents.command(context, LoopbackEvents.COMMAND_FAILED, command, mapOf("reason" to "failed by hand"))
        queue.failed(command)
        continueOrRest()
        return true
    }

    /** Sets the energy by hand; a stranded vehicle that gets energy carries on with its commands. */
    fun setEnergy(percent: Double) {
        val driving = activity as? Driving
        driving?.catchUp()
        val charging = charger.isCharging
        charger.stop()
        vehicle.battery.set(percent)
        if (charging) charger.start()
        driving?.energyChanged()
        if (stranded && !vehicle.battery.isEmpty) {
            stranded = false
            continueOrRest()
        }
    }

    private fun startNext() {
        val command = queue.pending.firstOrNull() ?: return rest()
        if (stranded) return
        charger.stop()
        vehicle.changeState(VehicleState.EXECUTING)
        val leg = Leg.of(command.step, context.plantModel, context.vehicle()) ?: return unknownPath(command)
        LoopbackEvents.command(context, LoopbackEvents.COMMAND_STARTED, command)
        val interval = settings.positionReportIntervalSimulatedMillis
        val stopAtEnd = !mayKeepGoing(command)
        begin(Driving(command, leg, velocity, stopAtEnd, planner(leg), vehicle, drain, time, interval, ::driven))
    }

    private fun planner(leg: Leg): Planner {
        val parameters = parameters()
        return { length, startVelocity, stopAtEnd ->
            val (acceleration, deceleration) = parameters.acceleration to parameters.deceleration
            VelocityProfile.plan(length, startVelocity, leg.maxVelocity, acceleration, deceleration, stopAtEnd)
        }
    }

    /** A vehicle brakes at the end of a command unless another one follows right away. */
    private fun mayKeepGoing(command: MovementCommand) =
        !command.hasOperation && !singleStepMode && queue.pending.size >= 2

    private fun begin(next: Activity) {
        activity = next
        if (!paused) next.resume()
    }

    private fun driven(driving: Driving) {
        activity = null
        if (!driving.arrived) return runOutOfEnergy(driving)
        vehicle.reportPoint(driving.command.step.destinationPoint)
        vehicle.place(driving.leg.to, driving.leg.heading)
        velocity = driving.endVelocity
        if (driving.command.hasOperation) operate(driving.command) else finish(driving.command)
    }

    private fun operate(command: MovementCommand) {
        velocity = 0.0
        val operating = Operating(command, time, parameters().operatingTimeMillis.toDouble(), ::operated)
        activity = operating
        if (command.operation == settings.rechargeOperation) {
            vehicle.changeState(VehicleState.CHARGING)
            charger.start()
        } else {
            vehicle.changeState(VehicleState.EXECUTING)
        }
        begin(operating)
    }

    private fun operated(command: MovementCommand) {
        activity = null
        val parameters = parameters()
        when (command.operation) {
            parameters.loadOperation -> vehicle.setLoaded(true)
            parameters.unloadOperation -> vehicle.setLoaded(false)
        }
        finish(command)
    }

    private fun finish(command: MovementCommand) {
        LoopbackEvents.command(context, LoopbackEvents.COMMAND_FINISHED, command)
        queue.executed(command)
        continueOrRest()
    }

    private fun continueOrRest() {
        // The kernel may already have sent and started the next command while we reported the last one.
        if (activity != null) return
        if (queue.pending.isNotEmpty() && !singleStepMode) startNext() else rest()
    }

    private fun rest() {
        velocity = 0.0
        if (!stranded) vehicle.changeState(if (charger.isCharging) VehicleState.CHARGING else VehicleState.IDLE)
    }

    private fun halt() {
        activity?.stop()
        activity = null
        velocity = 0.0
    }

    private fun fullyCharged() {
        if (activity == null && !stranded) vehicle.changeState(VehicleState.IDLE)
    }

    private fun runOutOfEnergy(driving: Driving) {
        velocity = 0.0
        stranded = true
        vehicle.battery.set(0.0)
        vehicle.changeState(VehicleState.ERROR)
        val where = driving.command.step.path ?: driving.command.step.destinationPoint
        notify("battery empty after ${driving.driven.roundToLong()} mm on $where; stopped until it gets energy")
        LoopbackEvents.command(
            context,
            LoopbackEvents.COMMAND_FAILED,
            driving.command,
            mapOf("reason" to "battery empty"),
        )
        queue.failed(driving.command)
    }

    private fun unknownPath(command: MovementCommand) {
        notify("path ${command.step.path} is not in the plant model; command for ${command.transportOrder} failed")
        LoopbackEvents.command(context, LoopbackEvents.COMMAND_FAILED, command, mapOf("reason" to "unknown path"))
        queue.failed(command)
        continueOrRest()
    }

    private fun notify(text: String) =
        context.notifyUser(NotificationLevel.IMPORTANT, "${context.vehicle().name}: $text")
}
