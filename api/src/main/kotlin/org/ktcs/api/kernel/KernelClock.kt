package org.ktcs.api.kernel

import java.time.Instant

/**
 * The kernel's time. In normal operation it follows the wall clock; in simulations it is virtual and jumps from
 * event to event, as fast as the CPU allows, with the same results for the same inputs.
 */
public interface KernelClock {
    /** The current time. */
    public fun now(): Instant

    /** Milliseconds since the kernel started; never goes backwards. */
    public fun elapsedMillis(): Long

    /**
     * Runs [action] in the kernel context after [delayMillis] (0: as soon as possible, after already queued work).
     * @return a handle that cancels the action if it has not run yet.
     */
    public fun schedule(delayMillis: Long, action: () -> Unit): Cancellable
}

/** Cancels something scheduled; cancelling twice or after it ran does nothing. */
public fun interface Cancellable {
    public fun cancel()
}
