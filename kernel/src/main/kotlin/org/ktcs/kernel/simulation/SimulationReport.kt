package org.ktcs.kernel.simulation

/** The figures of one simulation run, printed as `name: value` lines. */
data class SimulationReport(
    val plant: String,
    val vehicles: Int,
    val ordersCreated: Int,
    val ordersFinished: Int,
    val ordersFailed: Int,
    val makespanSimulatedSeconds: Double,
    val kernelCpuSeconds: Double,
    val wallSeconds: Double,
    val assignLatencyMillis: Percentiles,
    val routeMillis: Percentiles,
    val routeComputations: Int,
    val deadlocksDetected: Int,
    val deadlocksResolved: Int,
    val idleVehiclesMoved: Int,
    val doubleAllocations: Int,
    val sharedPositions: Int,
) {
    fun lines(): List<String> = listOf(
        "plant: $plant",
        "vehicles: $vehicles",
        "orders_created: $ordersCreated",
        "orders_finished: $ordersFinished",
        "orders_failed: $ordersFailed",
        "makespan_simulated_s: ${"%.1f".format(makespanSimulatedSeconds)}",
        "kernel_cpu_s: ${"%.2f".format(kernelCpuSeconds)}",
        "kernel_cpu_per_order_ms: ${"%.3f".format(
            if (ordersCreated == 0) 0.0 else kernelCpuSeconds * 1000 / ordersCreated,
        )}",
        "wall_s: ${"%.2f".format(wallSeconds)}",
        "assign_latency_p50_ms: ${"%.3f".format(assignLatencyMillis.p50)}",
        "assign_latency_p99_ms: ${"%.3f".format(assignLatencyMillis.p99)}",
        "route_computations: $routeComputations",
        "route_p50_ms: ${"%.3f".format(routeMillis.p50)}",
        "route_p99_ms: ${"%.3f".format(routeMillis.p99)}",
        "deadlocks_detected: $deadlocksDetected",
        "deadlocks_resolved: $deadlocksResolved",
        "idle_vehicles_moved: $idleVehiclesMoved",
        "double_allocations: $doubleAllocations",
        "shared_positions: $sharedPositions",
    )
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
