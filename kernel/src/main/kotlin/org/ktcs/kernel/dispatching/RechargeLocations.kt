package org.ktcs.kernel.dispatching

import org.ktcs.api.model.Location
import org.ktcs.api.model.Vehicle

/** Where a vehicle goes to recharge, and the access points of that location its route must avoid. */
internal data class RechargeTarget(val location: String, val blockedAccessPoints: Set<String>)

/**
 * Finds a recharge location for a vehicle (openTCS's `DefaultRechargePositionSupplier`): an unlocked location whose
 * type allows the vehicle's recharge operation, with a free access point whose link allows it too. The vehicle's
 * `tcs:assignedRechargeLocation` is the only choice if set; its `tcs:preferredRechargeLocation` comes first if free;
 * otherwise the location with the cheapest route wins.
 */
internal class RechargeLocations(private val run: DispatchRun, private val free: FreePositions) {
    private class Access(val location: Location, val freePoints: List<String>, val blockedPoints: Set<String>) {
        val target get() = RechargeTarget(location.name, blockedPoints)
    }

    fun choose(vehicle: Vehicle): RechargeTarget? {
        val usable = usableLocations(vehicle)
        vehicle.properties[DispatcherProperties.ASSIGNED_RECHARGE_LOCATION]?.let { name ->
            return usable.firstOrNull { it.location.name == name && costs(vehicle, it) != null }?.target
        }
        val preferred = vehicle.properties[DispatcherProperties.PREFERRED_RECHARGE_LOCATION]?.let { name ->
            usable.firstOrNull { it.location.name == name && costs(vehicle, it) != null }
        }
        return (preferred ?: cheapest(vehicle, usable))?.target
    }

    private fun usableLocations(vehicle: Vehicle): List<Access> = run.model.locations
        .filter { !it.locked && allowsRecharge(it, vehicle) && free.isFreeFor(it.name, vehicle) }
        .mapNotNull { access(it, vehicle) }

    private fun allowsRecharge(location: Location, vehicle: Vehicle): Boolean =
        run.model.locationType(location.type)?.allowedOperations?.contains(vehicle.rechargeOperation) == true

    private fun access(location: Location, vehicle: Vehicle): Access? {
        val operation = vehicle.rechargeOperation
        val points = location.links
            .filter { it.allowedOperations.isEmpty() || operation in it.allowedOperations }
            .map { it.point }
        val (freePoints, blocked) = points.partition { free.isFreeFor(it, vehicle) }
        if (freePoints.isEmpty()) return null
        // A route cannot avoid the point it starts from.
        return Access(location, freePoints, blocked.filterTo(HashSet()) { it != vehicle.currentPosition })
    }

    private fun costs(vehicle: Vehicle, access: Access): Long? =
        access.freePoints.mapNotNull { run.routes.costs(vehicle, it) }.minOrNull()

    private fun cheapest(vehicle: Vehicle, usable: List<Access>): Access? = usable
        .mapNotNull { access -> costs(vehicle, access)?.let { access to it } }
        .minWithOrNull(compareBy({ it.second }, { it.first.location.name }))
        ?.first
}
