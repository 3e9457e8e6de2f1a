package org.ktcs.kernel.dispatching

/**
 * Sends idle vehicles whose energy is degraded (at or below their good threshold) to recharge (openTCS's
 * `RechargeIdleVehiclesPhase`), the emptiest first, so it gets the closest free charger.
 */
internal class IdleVehicleRecharging(
    private val run: DispatchRun,
    private val idle: IdleVehicles,
    free: FreePositions,
    private val placer: IdleOrderPlacer,
) {
    private val locations = RechargeLocations(run, free)

    fun run() {
        idle.select(run.configuration.rechargeIdleVehiclesDelayMillis, CHARGE_ORDER_TYPE)
            .filter { it.isEnergyDegraded }
            .sortedBy { it.energyLevel }
            .forEach { vehicle ->
                locations.choose(vehicle)?.let { placer.recharge(vehicle, it.location, it.blockedAccessPoints) }
            }
    }
}
