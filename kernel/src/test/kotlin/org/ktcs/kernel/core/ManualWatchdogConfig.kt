package org.ktcs.kernel.core

import org.ktcs.kernel.config.ConfigLoader

/** A kernel whose deadlock watchdog a test runs by hand, with idle vehicles left where they stand. */
internal fun manualWatchdogConfig() = ConfigLoader().load(
    null,
    emptyMap(),
    listOf(
        "kernel.deadlockCheckInterval=0",
        "dispatcher.parkIdleVehicles=false",
        "dispatcher.rechargeIdleVehicles=false",
    ),
)
