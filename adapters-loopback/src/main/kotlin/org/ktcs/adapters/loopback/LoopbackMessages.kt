package org.ktcs.adapters.loopback

/**
 * The message types a loopback vehicle understands (openTCS's `LoopbackCommAdapterMessages`) and their parameters.
 * Where the brief's parameter name differs from openTCS's, both are accepted (e.g. `value` or `energyLevel`).
 */
object LoopbackMessages {
    private const val PREFIX = "tcs:virtualVehicle:"

    /** `position`: a point name; also moves the precise position to the point. */
    const val SET_POSITION: String = PREFIX + "setPosition"

    /** openTCS's older name for [SET_POSITION]. */
    const val INIT_POSITION: String = PREFIX + "initPosition"
    const val RESET_POSITION: String = PREFIX + "resetPosition"

    /** `x`, `y` and optionally `z` (default 0), whole millimetres. */
    const val SET_PRECISE_POSITION: String = PREFIX + "setPrecisePosition"
    const val RESET_PRECISE_POSITION: String = PREFIX + "resetPrecisePosition"

    /** `angle` (or `orientationAngle`): degrees. */
    const val SET_ORIENTATION_ANGLE: String = PREFIX + "setOrientationAngle"

    /** `value` (or `energyLevel`): percent, 0 to 100. */
    const val SET_ENERGY_LEVEL: String = PREFIX + "setEnergyLevel"

    /** `value` (or `loaded`): `true` or `false`. */
    const val SET_LOADED: String = PREFIX + "setLoaded"

    /** `value` (or `state`): a vehicle state name such as `ERROR`. */
    const val SET_STATE: String = PREFIX + "setState"

    /** `value` (or `enabled`): `true` or `false`. */
    const val SET_SINGLE_STEP_MODE_ENABLED: String = PREFIX + "setSingleStepModeEnabled"
    const val TRIGGER_SINGLE_STEP: String = PREFIX + "triggerSingleStep"

    /** `value`: how many times faster than the kernel clock this vehicle's simulated time runs (kTCS's own). */
    const val SET_TIME_FACTOR: String = PREFIX + "setTimeFactor"
    const val CURRENT_MOVEMENT_COMMAND_FAILED: String = PREFIX + "currentMovementCommandFailed"

    /** `key` and `value`. */
    const val SET_PROPERTY: String = PREFIX + "setProperty"

    /** `key`. */
    const val RESET_PROPERTY: String = PREFIX + "resetProperty"

    /** `type` (default [DEFAULT_EVENT_TYPE]); every other parameter becomes the event's payload. */
    const val PUBLISH_EVENT: String = PREFIX + "publishEvent"

    /** The type of an event published without a `type` parameter. */
    const val DEFAULT_EVENT_TYPE: String = PREFIX + "event"
}
