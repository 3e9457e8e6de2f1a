package org.ktcs.kernel.simulation

/** The figures of one simulation run, printed as `name: value` lines. */
data class SimulationReport(
    val plant: String,
    val vehicles: Int,
    val clock: String,
    val ordersCreated: Int,
    val ordersFinished: Int,
    val ordersFailed: Int,
    val ordersUnroutable: Int,
    val makespanSimulatedSeconds: Double,
    val kernelCpuSeconds: Double,
    val deadlocksDetected: Int,
    val deadlocksResolved: Int,
    val idleVehiclesMoved: Int,
    val retreats: Int = 0,
    val claimYields: Int = 0,
    val grantsHeldBack: Long,
    val wallSeconds: Double = 0.0,
    val assignLatencyMillis: Percentiles = Percentiles(0.0, 0.0),
    val assignWaitMillis: Percentiles = Percentiles(0.0, 0.0),
    val dispatchRunMillis: Percentiles = Percentiles(0.0, 0.0),
    val dispatchRuns: Int = 0,
    val firstWaveAssignments: Int = 0,
    val firstWaveMillis: Long = 0,
    val routeMillis: Percentiles = Percentiles(0.0, 0.0),
    val routeComputations: Int = 0,
    val doubleAllocations: Int = 0,
    val sharedPositions: Int = 0,
    val lowerBoundSeconds: Double = 0.0,
    val vehicleSeconds: Map<VehicleTimeUse, Double> = emptyMap(),
    val heldBackLines: List<String> = emptyList(),
    /** For a stalled batch, the vehicles standing with an order and what each waits for ([stalledVehicleLines]). */
    val stalledLines: List<String> = emptyList(),
) {
    fun lines(): List<String> = listOf(
        "plant: $plant",
        "vehicles: $vehicles",
        "clock: $clock",
        "orders_created: $ordersCreated",
        "orders_finished: $ordersFinished",
        "orders_failed: $ordersFailed",
        "orders_unroutable: $ordersUnroutable",
        "makespan_simulated_s: ${"%.1f".format(makespanSimulatedSeconds)}",
        "makespan_lower_bound_s: ${"%.1f".format(lowerBoundSeconds)}",
        "makespan_over_lower_bound: ${"%.2f".format(
            if (lowerBoundSeconds > 0) makespanSimulatedSeconds / lowerBoundSeconds else 0.0,
        )}",
    ) + vehicleTimeLines() + heldBackLines + listOf(
        "kernel_cpu_s: ${"%.2f".format(kernelCpuSeconds)}",
        "kernel_cpu_per_order_ms: ${"%.3f".format(
            if (ordersFinished == 0) 0.0 else kernelCpuSeconds * 1000 / ordersFinished,
        )}",
        "wall_s: ${"%.2f".format(wallSeconds)}",
        "assign_latency_p50_ms: ${"%.3f".format(assignLatencyMillis.p50)}",
        "assign_latency_p99_ms: ${"%.3f".format(assignLatencyMillis.p99)}",
        "assign_wait_p50_ms: ${"%.3f".format(assignWaitMillis.p50)}",
        "assign_wait_p99_ms: ${"%.3f".format(assignWaitMillis.p99)}",
        "dispatch_runs: $dispatchRuns",
        "dispatch_run_p50_ms: ${"%.3f".format(dispatchRunMillis.p50)}",
        "dispatch_run_p99_ms: ${"%.3f".format(dispatchRunMillis.p99)}",
        "first_wave_assignments: $firstWaveAssignments",
        "first_wave_ms: $firstWaveMillis",
        "route_computations: $routeComputations",
        "route_p50_ms: ${"%.3f".format(routeMillis.p50)}",
        "route_p99_ms: ${"%.3f".format(routeMillis.p99)}",
        "deadlocks_detected: $deadlocksDetected",
        "deadlocks_resolved: $deadlocksResolved",
        "grants_held_back_by_deadlock_avoidance: $grantsHeldBack",
        "retreats: $retreats",
        "claim_yields: $claimYields",
        "idle_vehicles_moved: $idleVehiclesMoved",
        "double_allocations: $doubleAllocations",
        "shared_positions: $sharedPositions",
    ) + stalledLines

    /** Where the vehicles' time went, summed over vehicles, with each use's share of the fleet's time. */
    private fun vehicleTimeLines(): List<String> {
        val total = vehicleSeconds.values.sum()
        return vehicleSeconds.map { (use, seconds) ->
            val share = if (total > 0) seconds * 100 / total else 0.0
            "vehicle_time_${use.label}_s: ${"%.1f".format(seconds)} (${"%.1f".format(share)}%)"
        }
    }
}

/** The median and the 99th percentile of some measurements. */
data class Percentiles(val p50: Double, val p99: Double) {
    companion object {
        fun of(values: List<Double>): Percentiles {
            if (values.isEmpty()) return Percentiles(0.0, 0.0)
            val sorted = values.sorted()
            fun at(q: Double) = sorted[((sorted.size - 1) * q).toInt()]
            return Percentiles(at(0.5), at(0.99))
        }
    }
}
