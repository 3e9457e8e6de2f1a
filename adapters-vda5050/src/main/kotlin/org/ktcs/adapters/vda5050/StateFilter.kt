package org.ktcs.adapters.vda5050

import org.ktcs.adapters.vda5050.protocol.BatteryState
import org.ktcs.adapters.vda5050.protocol.State

/**
 * Which `state` messages are worth a kernel task. A vehicle repeats its state every second, mostly unchanged but for
 * its header, timestamp, pose (reported on its own, see [VehicleReports.pose]), distance since the last node and the
 * battery's fraction of a percent: such a repetition changes nothing the driver does, unless the driver waits for the
 * vehicle to confirm something (an order update or a cancellation, sent again if not confirmed in time), the
 * connection changed, or the vehicle reports errors (a rejection counts per message). Checked on the link's thread,
 * before the message costs the kernel anything.
 */
internal class StateFilter {
    @Volatile private var everyMessage = true

    // The last message let through, as compared; on the link's threads, guarded by this.
    private var last: State? = null

    /** Whether [state] goes to the kernel: it differs from the last one that did, or the driver needs every one. */
    @Synchronized
    fun worthATask(state: State): Boolean {
        val essence = state.essence()
        val changed = essence != last
        last = essence
        return changed || everyMessage || state.errors.isNotEmpty()
    }

    /** From the kernel context: whether the driver needs every state message (it waits for a confirmation). */
    fun needEvery(every: Boolean) {
        everyMessage = every
    }

    /** The next state message goes to the kernel whatever it says (the driver was enabled or the connection changed). */
    @Synchronized
    fun reset() {
        last = null
    }

    private fun State.essence(): State = copy(
        headerId = 0,
        timestamp = "",
        agvPosition = null,
        distanceSinceLastNode = null,
        batteryState = BatteryState(batteryState.batteryCharge.toInt().toDouble(), batteryState.charging),
    )
}
