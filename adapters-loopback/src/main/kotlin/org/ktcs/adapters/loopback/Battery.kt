package org.ktcs.adapters.loopback

import kotlin.math.ceil
import kotlin.math.min

/**
 * The vehicle's energy in percent. Kept fractional so many short paths add up; reported as a whole percent rounded
 * up, so the kernel sees 0 % only when the battery is truly empty.
 */
internal class Battery(private val report: (Int) -> Unit) {
    var level: Double = 100.0
        private set
    private var reported: Int? = null

    val isEmpty: Boolean get() = level <= 0.0

    fun set(percent: Double) {
        level = percent.coerceIn(0.0, 100.0)
        // The epsilon keeps rounding noise (89.9999999 or 90.0000001) from flipping the reported value.
        val shown = ceil(level - 1e-9).toInt().coerceAtLeast(0)
        if (shown != reported) {
            reported = shown
            report(shown)
        }
    }

    /** Sets the level and reports it even if unchanged, e.g. when the driver is enabled again. */
    fun reset(percent: Double) {
        reported = null
        set(percent)
    }

    fun drain(percent: Double) = set(level - percent)
}

/** Uses [percentPerKm] of [battery]'s energy per kilometre driven. */
internal class Drain(private val battery: Battery, private val percentPerKm: Double) {
    fun drive(millimetres: Double) = battery.drain(millimetres * percentPerKm / MM_PER_KM)

    /** How far along a path of [length] mm the vehicle gets, having driven [driven] of it, before it runs empty. */
    fun reach(length: Double, driven: Double): Double =
        if (percentPerKm > 0.0) min(length, driven + battery.level / percentPerKm * MM_PER_KM) else length

    private companion object {
        const val MM_PER_KM = 1_000_000.0
    }
}
