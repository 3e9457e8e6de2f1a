package org.ktcs.adapters.vda5050

/** How a VDA 5050 completion is detected (`vda5050:movementCommandCompletedCondition`). */
enum class CompletionCondition { EDGE, EDGE_AND_NODE }

/** An MQTT topic below the vehicle's prefix, and the QoS (0, 1 or 2) used with it. */
data class TopicSetting(val name: String, val qos: Int)

/**
 * A VDA 5050 vehicle's configuration, read from its plant-model properties with openTCS's keys and defaults (openTCS
 * documentation, "VDA5050 2.0 driver: Driver configuration"), so a plant prepared for openTCS's driver works unchanged.
 */
data class Vda5050Properties(
    val version: String,
    val topicPrefix: String,
    val manufacturer: String,
    val serialNumber: String,
    val connection: TopicSetting,
    val state: TopicSetting,
    val visualization: TopicSetting,
    val factsheet: TopicSetting,
    val order: TopicSetting,
    val instantActions: TopicSetting,
    val validateIncomingMessages: Boolean,
    val rechargeOperation: String,
    val maxStepsBase: Int,
    val maxDistanceBase: Long,
    val maxStepsHorizon: Int,
    val minVisualizationIntervalMillis: Long,
    val vehicleLengthLoaded: Int?,
    val vehicleLengthUnloaded: Int?,
    val completion: CompletionCondition,
    val maxIgnoredRejections: Int,
    val lastNodeIdRequired: Boolean,
    val mapId: String?,
) {
    fun topic(setting: TopicSetting): String = "$topicPrefix/${setting.name}"

    companion object {
        const val PREFIX = "vda5050:"
        const val VERSION = "vda5050:version"
        const val TOPIC_PREFIX = "vda5050:topicPrefix"
        const val INTERFACE_NAME = "vda5050:interfaceName"
        const val MANUFACTURER = "vda5050:manufacturer"
        const val SERIAL_NUMBER = "vda5050:serialNumber"
        const val VALIDATE = "vda5050:validateIncomingMessages"
        const val RECHARGE_OPERATION = "vda5050:rechargeOperation"
        const val MAX_STEPS_BASE = "vda5050:maxStepsBase"
        const val MAX_DISTANCE_BASE = "vda5050:maxDistanceBase"
        const val MAX_STEPS_HORIZON = "vda5050:maxStepsHorizon"
        const val MIN_VISUALIZATION_INTERVAL = "vda5050:minVisualizationInterval"
        const val LENGTH_LOADED = "vda5050:vehicleLengthLoaded"
        const val LENGTH_UNLOADED = "vda5050:vehicleLengthUnloaded"
        const val COMPLETION = "vda5050:movementCommandCompletedCondition"
        const val MAX_IGNORED_REJECTIONS = "vda5050:maxIgnoredRejections"
        const val LAST_NODE_ID_REQUIRED = "vda5050:lastNodeIdRequiredForMovementCompletion"
        const val MAP_ID = "vda5050:mapId"

        /** The protocol versions this driver speaks. */
        val SUPPORTED_VERSIONS: Set<String> = setOf("2.0", "2.1")

        /**
         * Reads the properties of vehicle [vehicle]; a missing or unusable one is an [IllegalArgumentException] that
         * names the vehicle and the property.
         */
        fun read(vehicle: String, properties: Map<String, String>): Vda5050Properties =
            Reader(vehicle, properties).read()
    }

    private class Reader(private val vehicle: String, private val properties: Map<String, String>) {
        fun read(): Vda5050Properties {
            val version = required(VERSION)
            usable(VERSION, version.takeIf { v -> SUPPORTED_VERSIONS.any { v == it || v.startsWith("$it.") } }) {
                "one of ${SUPPORTED_VERSIONS.joinToString()}"
            }
            val manufacturer = required(MANUFACTURER)
            val serialNumber = required(SERIAL_NUMBER)
            val prefix = properties[TOPIC_PREFIX]?.takeIf { it.isNotBlank() }
                ?: properties[INTERFACE_NAME]?.takeIf { it.isNotBlank() }?.let { "$it/v2/$manufacturer/$serialNumber" }
                ?: fail(TOPIC_PREFIX, "is missing (and so is $INTERFACE_NAME, from which it would be derived)")
            return Vda5050Properties(
                version = version,
                topicPrefix = prefix,
                manufacturer = manufacturer,
                serialNumber = serialNumber,
                connection = topic("Connection", "connection"),
                state = topic("State", "state"),
                visualization = topic("Visualization", "visualization"),
                factsheet = topic("Factsheet", "factsheet"),
                order = topic("Order", "order"),
                instantActions = topic("InstantActions", "instantActions"),
                validateIncomingMessages = boolean(VALIDATE, true),
                rechargeOperation = properties[RECHARGE_OPERATION]?.takeIf { it.isNotBlank() } ?: "Charge",
                maxStepsBase = int(MAX_STEPS_BASE, 2, 1),
                maxDistanceBase = long(MAX_DISTANCE_BASE, Long.MAX_VALUE),
                maxStepsHorizon = int(MAX_STEPS_HORIZON, Int.MAX_VALUE, 0),
                minVisualizationIntervalMillis = long(MIN_VISUALIZATION_INTERVAL, 500),
                vehicleLengthLoaded = properties[LENGTH_LOADED]?.let { int(LENGTH_LOADED, 0, 1) },
                vehicleLengthUnloaded = properties[LENGTH_UNLOADED]?.let { int(LENGTH_UNLOADED, 0, 1) },
                completion = enum(COMPLETION, CompletionCondition.EDGE_AND_NODE),
                maxIgnoredRejections = int(MAX_IGNORED_REJECTIONS, 0, 0),
                lastNodeIdRequired = boolean(LAST_NODE_ID_REQUIRED, false),
                mapId = properties[MAP_ID],
            )
        }

        private fun topic(suffix: String, default: String): TopicSetting {
            val nameKey = "${PREFIX}topic${suffix}Name"
            val qosKey = "${PREFIX}topic${suffix}Qos"
            val name = properties[nameKey]?.takeIf { it.isNotBlank() } ?: default
            val qos = properties[qosKey]?.let { value ->
                QOS_NAMES[value.trim().lowercase()]
                    ?: fail(qosKey, "must be at_most_once, at_least_once, exactly_once, 0, 1 or 2, was '$value'")
            } ?: 0
            return TopicSetting(name, qos)
        }

        private fun required(key: String): String =
            properties[key]?.takeIf { it.isNotBlank() } ?: fail(key, "is missing")

        private fun boolean(key: String, default: Boolean): Boolean = properties[key]?.let {
            it.trim().lowercase().toBooleanStrictOrNull() ?: fail(key, "must be true or false, was '$it'")
        } ?: default

        private fun int(key: String, default: Int, min: Int): Int = properties[key]?.let {
            it.trim().toIntOrNull()?.takeIf { value -> value >= min }
                ?: fail(key, "must be a whole number of at least $min, was '$it'")
        } ?: default

        private fun long(key: String, default: Long): Long = properties[key]?.let {
            it.trim().toLongOrNull()?.takeIf { value -> value >= 0 }
                ?: fail(key, "must be a whole number of at least 0, was '$it'")
        } ?: default

        private inline fun <reified E : Enum<E>> enum(key: String, default: E): E = properties[key]?.let { value ->
            enumValues<E>().firstOrNull { it.name.equals(value.trim(), ignoreCase = true) }
                ?: fail(key, "must be one of ${enumValues<E>().joinToString()}, was '$value'")
        } ?: default

        private inline fun usable(key: String, value: String?, expected: () -> String) {
            if (value == null) fail(key, "must be ${expected()}, was '${properties[key]}'")
        }

        private fun fail(key: String, problem: String): Nothing =
            throw IllegalArgumentException("vehicle $vehicle: property $key $problem")
    }
}

private val QOS_NAMES = mapOf(
    "at_most_once" to 0,
    "at_least_once" to 1,
    "exactly_once" to 2,
    "0" to 0,
    "1" to 1,
    "2" to 2,
)
