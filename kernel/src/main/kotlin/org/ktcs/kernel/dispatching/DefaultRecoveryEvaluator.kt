package org.ktcs.kernel.dispatching

import org.ktcs.api.dispatching.RecoveryEvaluator

/**
 * openTCS 4.x's recovery evaluator: a charging vehicle has recovered once its energy level reaches both its
 * `sufficientlyRecharged` threshold and [threshold] × 100 percent, so a vehicle whose sufficient level is set very
 * low still charges to a useful level before it takes orders again.
 *
 * @param threshold the share of a full battery a vehicle needs at least, from 0.0 to 1.0
 *   (`defaultrecoveryevaluator.threshold`, default 0.7).
 */
class DefaultRecoveryEvaluator(private val threshold: Double = 0.7) : RecoveryEvaluator {
    init {
        require(threshold in 0.0..1.0) { "threshold must be between 0.0 and 1.0, was $threshold" }
    }

    override fun isRecovered(energyLevel: Int, sufficientlyRecharged: Int, fullyRecharged: Int): Boolean =
        energyLevel >= sufficientlyRecharged && energyLevel >= threshold * 100
}
