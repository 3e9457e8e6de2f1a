package org.ktcs.adapters.loopback

import org.ktcs.api.kernel.Cancellable
import kotlin.math.floor

/**
 * Charges [battery] by [percentPerSecond] while running, with one scheduled event per whole percent, and calls
 * [onFull] when it reaches 100 %.
 */
internal class Charger(
    private val time: SimulatedTime,
    private val battery: Battery,
    private val percentPerSecond: Double,
    private val onFull: () -> Unit,
) {
    private var lastUpdate: Double? = null
    private var handle: Cancellable? = null

    val isCharging: Boolean get() = lastUpdate != null

    fun start() {
        if (isCharging) return
        lastUpdate = time.nowMillis()
        scheduleNext()
    }

    /** Stops charging, keeping the energy gained so far. */
    fun stop() {
        val since = lastUpdate ?: return
        battery.set(battery.level + (time.nowMillis() - since) / 1000 * percentPerSecond)
        lastUpdate = null
        handle?.cancel()
        handle = null
    }

    private fun scheduleNext() {
        if (battery.level >= 100.0) return full()
        if (percentPerSecond <= 0.0) return
        val target = (floor(battery.level) + 1).coerceAtMost(100.0)
        handle = time.schedule((target - battery.level) / percentPerSecond * 1000) {
            lastUpdate = time.nowMillis()
            battery.set(target)
            scheduleNext()
        }
    }

    private fun full() {
        lastUpdate = null
        handle = null
        onFull()
    }
}
