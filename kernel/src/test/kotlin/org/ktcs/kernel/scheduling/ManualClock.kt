package org.ktcs.kernel.scheduling

import org.ktcs.api.kernel.Cancellable
import org.ktcs.api.kernel.KernelClock
import java.time.Instant
import java.util.PriorityQueue

/** A [KernelClock] whose scheduled actions run only when a test calls [drain] or [advance]. */
class ManualClock : KernelClock {
    private class Task(val due: Long, val seq: Long, val action: () -> Unit) {
        var cancelled = false
    }

    private val tasks = PriorityQueue(compareBy<Task>({ it.due }, { it.seq }))
    private var millis = 0L
    private var seq = 0L

    /** How many scheduled actions wait to run, cancelled ones included. */
    val queued: Int get() = tasks.size

    override fun now(): Instant = Instant.EPOCH.plusMillis(millis)

    override fun elapsedMillis(): Long = millis

    override fun schedule(delayMillis: Long, action: () -> Unit): Cancellable {
        val task = Task(millis + delayMillis, seq++, action)
        tasks += task
        return Cancellable { task.cancelled = true }
    }

    /** Runs everything due now, including what those actions schedule for now. */
    fun drain() {
        while (tasks.peek()?.let { it.due <= millis } == true) {
            val task = tasks.poll()
            if (!task.cancelled) task.action()
        }
    }

    fun advance(delayMillis: Long) {
        millis += delayMillis
        drain()
    }
}
