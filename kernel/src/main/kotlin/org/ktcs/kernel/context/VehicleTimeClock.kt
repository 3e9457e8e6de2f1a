package org.ktcs.kernel.context

import org.ktcs.api.kernel.Cancellable
import org.ktcs.api.kernel.KernelClock
import java.time.Instant
import kotlin.math.roundToLong

/**
 * The kernel clock as the vehicles live it: where they move [timeFactor] times faster than the kernel clock (simulated
 * vehicles), its milliseconds pass that many times faster. Traffic control's timers (how long a grant may be held back
 * before it counts as stuck, the park test's patience) run on it, so a plant behaves the same at any time factor:
 * ten seconds of patience measured on the kernel clock are a thousand seconds of driving at time factor 100.
 */
class VehicleTimeClock(private val clock: KernelClock, private val timeFactor: Double) : KernelClock {
    init {
        require(timeFactor > 0 && timeFactor.isFinite()) { "time factor must be positive, was $timeFactor" }
    }

    override fun now(): Instant = clock.now()

    override fun elapsedMillis(): Long = (clock.elapsedMillis() * timeFactor).toLong()

    override fun schedule(delayMillis: Long, action: () -> Unit): Cancellable =
        clock.schedule(kernelMillis(delayMillis), action)

    /** How many kernel-clock milliseconds [vehicleMillis] of vehicle time take. */
    fun kernelMillis(vehicleMillis: Long): Long = (vehicleMillis / timeFactor).roundToLong()
}
