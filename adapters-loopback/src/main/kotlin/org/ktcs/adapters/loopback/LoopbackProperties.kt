package org.ktcs.adapters.loopback

import org.ktcs.adapters.loopback.LoopbackProperties.ACCELERATION
import org.ktcs.adapters.loopback.LoopbackProperties.DECELERATION
import org.ktcs.adapters.loopback.LoopbackProperties.LOAD_OPERATION
import org.ktcs.adapters.loopback.LoopbackProperties.OPERATING_TIME
import org.ktcs.adapters.loopback.LoopbackProperties.UNLOAD_OPERATION
import org.ktcs.api.model.Vehicle
import org.slf4j.LoggerFactory
import kotlin.math.abs

/** Vehicle properties the loopback driver reads, with openTCS's keys. */
object LoopbackProperties {
    /** The point a vehicle starts at when its driver is enabled. */
    const val INITIAL_POSITION: String = "loopback:initialPosition"

    /** Simulated ms an operation takes. */
    const val OPERATING_TIME: String = "loopback:operatingTime"

    /** mm/s². */
    const val ACCELERATION: String = "loopback:acceleration"

    /** mm/s²; the sign is ignored because openTCS models give it negative. */
    const val DECELERATION: String = "loopback:deceleration"

    /** The operation that loads the vehicle. */
    const val LOAD_OPERATION: String = "loopback:loadOperation"

    /** The operation that unloads the vehicle. */
    const val UNLOAD_OPERATION: String = "loopback:unloadOperation"
}

/** The settings for one vehicle: [LoopbackSettings] overridden by its properties. */
internal data class VehicleParameters(
    val operatingTimeMillis: Long,
    val acceleration: Double,
    val deceleration: Double,
    val loadOperation: String,
    val unloadOperation: String,
) {
    companion object {
        private val log = LoggerFactory.getLogger(VehicleParameters::class.java)

        fun of(vehicle: Vehicle, defaults: LoopbackSettings): VehicleParameters {
            val properties = vehicle.properties
            fun number(key: String, default: Double, zeroAllowed: Boolean = false): Double {
                val text = properties[key] ?: return default
                val value = text.trim().toDoubleOrNull()?.let(::abs)
                    ?.takeIf { it.isFinite() && (it > 0.0 || zeroAllowed) }
                if (value == null) log.warn("{}: ignoring property {}={}, not a usable number", vehicle.name, key, text)
                return value ?: default
            }
            return VehicleParameters(
                operatingTimeMillis = number(OPERATING_TIME, defaults.operatingTimeMillis.toDouble(), true).toLong(),
                acceleration = number(ACCELERATION, defaults.acceleration),
                deceleration = number(DECELERATION, defaults.deceleration),
                loadOperation = properties[LOAD_OPERATION] ?: defaults.loadOperation,
                unloadOperation = properties[UNLOAD_OPERATION] ?: defaults.unloadOperation,
            )
        }
    }
}
