package org.ktcs.kernel.context

import org.ktcs.api.kernel.Cancellable

/**
 * The tasks to run right after the current kernel task ([KernelContext.scheduleNext]), in the order they were asked
 * for. Used only on the kernel thread. A follow-up asked for by a follow-up is not one: it goes to the back of the
 * context's queue ([later]), so that follow-ups cannot keep the queued tasks waiting for good.
 */
internal class FollowUps(private val later: (() -> Unit) -> Cancellable) {
    private class FollowUp(val action: () -> Unit) {
        var cancelled = false
    }

    private val pending = ArrayDeque<FollowUp>()
    private var running = false

    fun add(action: () -> Unit): Cancellable {
        if (running) return later(action)
        val followUp = FollowUp(action)
        pending.addLast(followUp)
        return Cancellable { followUp.cancelled = true }
    }

    /** Runs the follow-ups asked for so far, each with [run] (which must not let an exception escape). */
    fun runAll(run: (() -> Unit) -> Unit) {
        if (pending.isEmpty()) return
        running = true
        try {
            while (true) {
                val next = pending.removeFirstOrNull() ?: break
                if (!next.cancelled) run(next.action)
            }
        } finally {
            running = false
        }
    }
}
