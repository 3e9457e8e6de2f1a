package org.ktcs.kernel.dispatching

import org.ktcs.api.model.Vehicle
import org.ktcs.api.model.Vehicle.Companion.ANY_ORDER_TYPE

/** Whether the vehicle may take orders of [type]: both its acceptable and its allowed order types admit it. */
internal fun Vehicle.accepts(type: String): Boolean =
    acceptableOrderTypes.any { it.name == type || it.name == ANY_ORDER_TYPE } &&
        (type in allowedOrderTypes || ANY_ORDER_TYPE in allowedOrderTypes)

/**
 * The vehicle's priority for orders of [type], lower is preferred: an exact acceptable type counts before `*`, and a
 * type it does not accept at all comes last.
 */
internal fun Vehicle.orderTypePriority(type: String): Int =
    priorityOf(type) ?: priorityOf(ANY_ORDER_TYPE) ?: Int.MAX_VALUE

private fun Vehicle.priorityOf(name: String): Int? =
    acceptableOrderTypes.filter { it.name == name }.minOfOrNull { it.priority }

/** Whether the energy level is at or below the critical threshold. */
internal val Vehicle.isEnergyCritical: Boolean get() = energyLevel <= energyLevelThresholdSet.critical

/** Whether the energy level is at or below the good threshold. */
internal val Vehicle.isEnergyDegraded: Boolean get() = energyLevel <= energyLevelThresholdSet.good
