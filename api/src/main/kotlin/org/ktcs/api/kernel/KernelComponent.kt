package org.ktcs.api.kernel

/**
 * A replaceable part of the kernel (router, dispatcher, scheduler, recovery evaluator, …). The kernel creates one
 * instance of each, calls [initialize] once before use and [terminate] once when it stops.
 *
 * Every method of a component is called in the kernel context (one thread at a time), so a component needs no
 * locks of its own.
 */
public interface KernelComponent {
    /** Prepares the component for use; called once. */
    public fun initialize() {}

    /** Releases what the component holds; called once, after which it is not used again. */
    public fun terminate() {}
}
