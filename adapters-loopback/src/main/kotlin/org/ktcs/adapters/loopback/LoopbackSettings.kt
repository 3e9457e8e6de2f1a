package org.ktcs.adapters.loopback

import kotlin.math.roundToLong

/**
 * How loopback vehicles behave unless a vehicle's properties (see [LoopbackProperties]) say otherwise.
 *
 * @property timeFactor simulated time runs this many times faster than the kernel clock.
 * @property operatingTimeMillis how long an operation at a location takes, in simulated ms.
 * @property acceleration mm/s².
 * @property deceleration mm/s², a positive number.
 * @property loadOperation the operation that fills the load handling device.
 * @property unloadOperation the operation that empties the load handling device.
 * @property rechargeOperation the operation that recharges the vehicle.
 * @property rechargePercentPerSecond how fast a charging vehicle gains energy (simulated time).
 * @property energyDrainPercentPerKm energy used per kilometre driven; 0 never discharges, as openTCS's loopback
 *   (openTCS issue #183).
 * @property commandQueueCapacity how many movement commands a vehicle holds at a time.
 * @property placeUnpositionedVehicles place a vehicle that has no start point on a free park position or point.
 * @property positionReportIntervalMillis kernel-clock ms (wall-clock time, whatever the time factor) between
 *   precise-position reports while driving; 0 reports only at points, which keeps long simulations fast. Reports cost
 *   the kernel per second of its clock, so a faster simulation must not send more of them per second.
 */
data class LoopbackSettings(
    val timeFactor: Double = LoopbackConfigKeys.timeFactor.default,
    val operatingTimeMillis: Long = LoopbackConfigKeys.operatingTime.default,
    val acceleration: Double = LoopbackConfigKeys.acceleration.default,
    val deceleration: Double = LoopbackConfigKeys.deceleration.default,
    val loadOperation: String = "Load cargo",
    val unloadOperation: String = "Unload cargo",
    val rechargeOperation: String = "CHARGE",
    val rechargePercentPerSecond: Double = LoopbackConfigKeys.rechargeRate.default,
    val energyDrainPercentPerKm: Double = LoopbackConfigKeys.energyDrain.default,
    val commandQueueCapacity: Int = 2,
    val positionReportIntervalMillis: Long = LoopbackConfigKeys.positionReportInterval.default,
    val placeUnpositionedVehicles: Boolean = LoopbackConfigKeys.placeUnpositionedVehicles.default,
) {
    init {
        require(timeFactor > 0.0 && timeFactor.isFinite()) { "timeFactor must be positive, was $timeFactor" }
        require(operatingTimeMillis >= 0) { "operatingTimeMillis must not be negative, was $operatingTimeMillis" }
        require(acceleration > 0.0) { "acceleration must be positive, was $acceleration" }
        require(deceleration > 0.0) { "deceleration must be positive, was $deceleration" }
        require(rechargePercentPerSecond >= 0.0) { "rechargePercentPerSecond must not be negative" }
        require(energyDrainPercentPerKm >= 0.0) { "energyDrainPercentPerKm must not be negative" }
        require(commandQueueCapacity >= 1) { "commandQueueCapacity must be at least 1, was $commandQueueCapacity" }
        require(positionReportIntervalMillis >= 0) { "positionReportIntervalMillis must not be negative" }
    }

    /** [positionReportIntervalMillis] in simulated ms, the time a vehicle's motion runs on. */
    val positionReportIntervalSimulatedMillis: Long
        get() = (positionReportIntervalMillis * timeFactor).roundToLong()
}
