package org.ktcs.api.dispatching

import org.ktcs.api.kernel.KernelComponent

/**
 * Decides which vehicle does which transport order, and sends idle vehicles to recharge or park.
 *
 * The kernel runs [dispatch] in the kernel context whenever an order becomes DISPATCHABLE or a vehicle may have
 * become free for work (and, as a safety net, periodically). Activating new orders (RAW → ACTIVE → DISPATCHABLE,
 * dependencies, UNROUTABLE) and following an assigned order to its end are the kernel's job; a dispatcher only
 * assigns through its [DispatchContext].
 */
public interface Dispatcher : KernelComponent {
    /** Assigns what can be assigned now. */
    public fun dispatch()
}

/**
 * Decides when a charging vehicle has recovered enough energy to take orders again (openTCS 4.x's recovery
 * evaluator, default threshold 0.7).
 */
public interface RecoveryEvaluator : KernelComponent {
    /** Whether [energyLevel] percent is enough for a vehicle with these thresholds to take orders again. */
    public fun isRecovered(energyLevel: Int, sufficientlyRecharged: Int, fullyRecharged: Int): Boolean
}
