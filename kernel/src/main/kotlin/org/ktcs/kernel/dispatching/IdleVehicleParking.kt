package org.ktcs.kernel.dispatching

import org.ktcs.api.model.Vehicle

/**
 * Sends idle vehicles to park (openTCS's `PrioritizedReparkPhase`, `PrioritizedParkingPhase` and
 * `ParkIdleVehiclesPhase`). Parked vehicles move on to better park points first, if configured, the one on the worst
 * point first; vehicles with an assigned parking position stay where they are. Then vehicles that are not on a park
 * point get one.
 */
internal class IdleVehicleParking(
    private val run: DispatchRun,
    private val idle: IdleVehicles,
    free: FreePositions,
    private val placer: IdleOrderPlacer,
) {
    private val positions = ParkingPositions(run, free)

    fun run() {
        val (parked, unparked) = idle.select(run.configuration.parkIdleVehiclesDelayMillis, PARK_ORDER_TYPE)
            .partition { positions.isParkPosition(it.currentPosition) }
        if (run.configuration.considerParkingPositionPriorities &&
            run.configuration.reparkVehiclesToHigherPriorityPositions
        ) {
            repark(parked)
        }
        unparked.forEach { vehicle -> positions.forIdle(vehicle)?.let { placer.park(vehicle, it) } }
    }

    private fun repark(parked: List<Vehicle>) {
        parked.filter { DispatcherProperties.ASSIGNED_PARKING_POSITION !in it.properties }
            .sortedByDescending { positions.priority(it.currentPosition) ?: Int.MAX_VALUE }
            .forEach { vehicle -> positions.forRepark(vehicle)?.let { placer.park(vehicle, it) } }
    }
}
