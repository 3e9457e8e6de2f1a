package org.ktcs.kernel.vehicles

import org.ktcs.api.model.ProcState
import org.ktcs.api.model.Vehicle
import org.ktcs.api.model.VehicleState

/** The vehicle with a new processing state, time-stamped if it changed. */
internal fun Vehicle.withProcState(state: ProcState, env: VehicleEnvironment): Vehicle =
    if (procState == state) this else copy(procState = state, procStateTimestamp = env.context.now())

/** The vehicle with a new reported state, time-stamped if it changed. */
internal fun Vehicle.withState(state: VehicleState, env: VehicleEnvironment): Vehicle =
    if (this.state == state) this else copy(state = state, stateTimestamp = env.context.now())
