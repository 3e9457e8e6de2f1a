package org.ktcs.kernel.core

/**
 * Which vehicles the deadlock watchdog leaves out of its cycle search because they make progress: a vehicle carrying
 * out a command (driving a step or operating at a station) will report and free what it leaves, and a cycle of waits
 * through it often ends then by itself (a vehicle driving into a bay to let another pass still "waits" for its next
 * step). Such a cycle is no deadlock yet; if it lasts, it is found once the vehicle has stopped. A vehicle whose driver
 * has reported no command carried out for [patienceChecks] checks counts as stopped, so a driver that reports late or
 * never does not hide a deadlock for good (the stranded-vehicle watchdog reports such a vehicle too).
 */
internal class MovingVehicles(private val state: KernelState, private val patienceChecks: Long) {
    private class Seen(val commandsDone: Long, val sinceCheck: Long)

    private val seen = HashMap<String, Seen>()
    private var checks = 0L

    /** Starts a check; [isMoving] answers as of now. */
    fun startCheck() {
        checks++
    }

    fun isMoving(vehicle: String): Boolean {
        val controller = state.controllers.controller(vehicle)
        if (!controller.isMoving) {
            seen.remove(vehicle)
            return false
        }
        val last = seen[vehicle]
        if (last == null || last.commandsDone != controller.commandsDone) {
            seen[vehicle] = Seen(controller.commandsDone, checks)
            return true
        }
        return checks - last.sinceCheck < patienceChecks
    }
}
