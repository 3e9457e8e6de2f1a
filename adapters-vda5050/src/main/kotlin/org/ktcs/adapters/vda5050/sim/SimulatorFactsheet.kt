package org.ktcs.adapters.vda5050.sim

import kotlinx.serialization.json.add
import kotlinx.serialization.json.buildJsonObject
import kotlinx.serialization.json.put
import kotlinx.serialization.json.putJsonArray
import kotlinx.serialization.json.putJsonObject
import org.ktcs.adapters.vda5050.protocol.Vda
import java.time.Instant

/** The factsheet a simulated vehicle sends when asked: a carrier that picks and drops, with its limits. */
internal object SimulatorFactsheet {
    fun json(spec: SimulatedVehicleSpec): String = buildJsonObject {
        put("headerId", 0)
        put("timestamp", Instant.now().toString())
        put("version", Vda.PROTOCOL_VERSION)
        put("manufacturer", spec.manufacturer)
        put("serialNumber", spec.serialNumber)
        putJsonObject("typeSpecification") {
            put("seriesName", "kTCS simulated vehicle")
            put("agvKinematic", "DIFF")
            put("agvClass", "CARRIER")
            put("maxLoadMass", 500)
            putJsonArray("localizationTypes") { add("NATURAL") }
            putJsonArray("navigationTypes") { add("AUTONOMOUS") }
        }
        putJsonObject("physicalParameters") {
            put("speedMin", 0.0)
            put("speedMax", spec.speedMetresPerSecond)
            put("accelerationMax", 1.0)
            put("decelerationMax", 1.0)
            put("heightMax", 0.5)
            put("width", 0.8)
            put("length", 1.2)
        }
        putJsonObject("protocolLimits") {
            putJsonObject("maxStringLens") { put("idLen", 100) }
            putJsonObject("maxArrayLens") {
                put("order.nodes", 200)
                put("order.edges", 200)
            }
            putJsonObject("timing") {
                put("minOrderInterval", 0.1)
                put("minStateInterval", spec.stateIntervalMillis / 1000.0)
            }
        }
        putJsonObject("protocolFeatures") {
            putJsonArray("optionalParameters") {}
            putJsonArray("agvActions") {
                listOf(Vda.PICK, Vda.DROP, Vda.START_CHARGING).forEach { type ->
                    add(
                        buildJsonObject {
                            put("actionType", type)
                            putJsonArray("actionScopes") { add("NODE") }
                        },
                    )
                }
                listOf(
                    Vda.CANCEL_ORDER,
                    Vda.START_PAUSE,
                    Vda.STOP_PAUSE,
                    Vda.INIT_POSITION,
                    Vda.STATE_REQUEST,
                    Vda.FACTSHEET_REQUEST,
                )
                    .forEach { type ->
                        add(
                            buildJsonObject {
                                put("actionType", type)
                                putJsonArray("actionScopes") { add("INSTANT") }
                            },
                        )
                    }
            }
        }
        putJsonObject("agvGeometry") {}
        putJsonObject("loadSpecification") {}
    }.toString()
}
