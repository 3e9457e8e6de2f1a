package org.ktcs.adapters.loopback

import org.ktcs.extension.config.booleanSetting
import org.ktcs.extension.config.doubleSetting
import org.ktcs.extension.config.longSetting
import org.ktcs.extension.config.positiveDoubleSetting

/** The loopback driver's configuration keys (`loopback.*`), declared by [LoopbackExtension]. */
object LoopbackConfigKeys {
    val placeUnpositionedVehicles = booleanSetting(
        "loopback.placeUnpositionedVehicles",
        true,
        "Place a simulated vehicle without loopback:initialPosition on a free park position (else a free point) " +
            "when it starts, and say where in a notification.",
    )
    val timeFactor = positiveDoubleSetting(
        "loopback.timeFactor",
        1.0,
        "How much faster than real time the simulated loopback vehicles move (2.0: twice as fast).",
    )
    val operatingTime = longSetting(
        "loopback.operatingTime",
        5000,
        0L..3_600_000L,
        "Simulated milliseconds an operation takes (vehicle property loopback:operatingTime overrides).",
    )
    val acceleration = positiveDoubleSetting(
        "loopback.acceleration",
        500.0,
        "Simulated acceleration in mm/s² (vehicle property loopback:acceleration overrides).",
    )
    val deceleration = positiveDoubleSetting(
        "loopback.deceleration",
        500.0,
        "Simulated deceleration in mm/s² (vehicle property loopback:deceleration overrides).",
    )
    val rechargeRate = doubleSetting(
        "loopback.rechargePercentPerSecond",
        1.0,
        0.0..100.0,
        "Percent of energy a charging simulated vehicle gains per second.",
    )
    val energyDrain = doubleSetting(
        "loopback.energyDrainPercentPerKm",
        10.0,
        0.0..10_000.0,
        "Percent of energy a simulated vehicle uses per kilometre driven (openTCS's never drains).",
    )
    val positionReportInterval = longSetting(
        "loopback.positionReportInterval",
        500,
        0L..60_000L,
        "Milliseconds of real (kernel-clock) time between precise-position reports while driving, whatever " +
            "loopback.timeFactor (0: only at points).",
    )

    val all = listOf(
        placeUnpositionedVehicles,
        timeFactor,
        operatingTime,
        acceleration,
        deceleration,
        rechargeRate,
        energyDrain,
        positionReportInterval,
    )
}
