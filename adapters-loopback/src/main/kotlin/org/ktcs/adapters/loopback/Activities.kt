package org.ktcs.adapters.loopback

import org.ktcs.api.driver.MovementCommand

/** What the simulated vehicle is busy with for the command it carries out. */
internal sealed interface Activity {
    val command: MovementCommand

    fun pause()

    fun resume()

    /** Ends the activity early, leaving the vehicle where it is. */
    fun stop()
}

/** Plans driving a length from a start velocity, braking to a stop at the end or not. */
internal typealias Planner = (length: Double, startVelocity: Double, stopAtEnd: Boolean) -> Motion

/**
 * Driving [leg] for [command], reporting positions and using energy on the way; ends with [onEnd] once the vehicle
 * [arrived] or ran out of energy. Starts paused.
 */
internal class Driving(
    override val command: MovementCommand,
    val leg: Leg,
    startVelocity: Double,
    stopAtEnd: Boolean,
    private val plan: Planner,
    private val vehicle: VirtualVehicle,
    private val drain: Drain,
    private val time: SimulatedTime,
    private val reportIntervalMillis: Long,
    private val onEnd: (Driving) -> Unit,
) : Activity {
    var stopAtEnd: Boolean = stopAtEnd
        private set
    var driven: Double = 0.0
        private set
    var arrived: Boolean = false
        private set

    /** Where on the leg the current trip started; a trip is replaced when the vehicle decides to keep going. */
    private var offset = 0.0
    private var trip = tripFor(plan(leg.length, startVelocity, stopAtEnd))

    val endVelocity: Double get() = if (stopAtEnd) 0.0 else trip.motion.endVelocity

    /** Accounts for the energy used up to now, without a position report. */
    fun catchUp() = account(offset + trip.distance)

    /** Another command follows: keep the velocity at the end instead of braking to a stop. */
    fun keepGoing() {
        if (!stopAtEnd) return
        stopAtEnd = false
        val running = trip.isRunning
        trip.pause()
        catchUp()
        val velocity = trip.velocity
        offset = driven
        // A trip's phases may add up to a hair more than the leg (2.3e-13 m seen on a 2 m path): what is left is never negative.
        trip = tripFor(plan((leg.length - offset).coerceAtLeast(0.0), velocity, false))
        if (running) trip.start()
    }

    /** The battery level was set by hand (after [catchUp]): the vehicle now gets as far as the new level allows. */
    fun energyChanged() = trip.endAt(drain.reach(leg.length, driven) - offset)

    override fun pause() = trip.pause()

    override fun resume() = trip.start()

    override fun stop() {
        trip.pause()
        advance(offset + trip.distance)
    }

    private fun tripFor(motion: Motion) = Trip(
        time,
        motion,
        drain.reach(leg.length, offset) - offset,
        reportIntervalMillis,
        { advance(offset + it) },
        ::end,
    )

    private fun advance(distance: Double) {
        account(distance)
        vehicle.place(leg.positionAt(distance), leg.heading)
    }

    private fun account(distance: Double) {
        drain.drive(distance - driven)
        driven = distance
    }

    private fun end() {
        if (offset + trip.endDistance < leg.length) {
            advance(offset + trip.endDistance)
        } else {
            // The arrival reports the point itself.
            account(leg.length)
            arrived = true
        }
        onEnd(this)
    }
}

/** Performing [command]'s operation for [durationMillis]; then [onDone]. Starts paused. */
internal class Operating(
    override val command: MovementCommand,
    time: SimulatedTime,
    durationMillis: Double,
    onDone: (MovementCommand) -> Unit,
) : Activity {
    private val timer = PausableTimer(time, durationMillis) { onDone(command) }

    override fun pause() = timer.pause()

    override fun resume() = timer.start()

    override fun stop() = timer.pause()
}
