package org.ktcs.adapters.vda5050.protocol

import kotlinx.serialization.Serializable
import kotlinx.serialization.json.Json
import kotlinx.serialization.json.JsonElement

/** The JSON of VDA 5050 messages: optional fields left out when unset, unknown fields of newer versions ignored. */
val Vda5050Json: Json = Json {
    ignoreUnknownKeys = true
    explicitNulls = false
    encodeDefaults = true
}

/** The header every VDA 5050 message starts with. */
@Serializable
data class Header(
    val headerId: Long,
    val timestamp: String,
    val version: String,
    val manufacturer: String,
    val serialNumber: String,
)

/** An `order` message: the nodes and edges a vehicle is to travel, base (`released`) and horizon. */
@Serializable
data class Order(
    val headerId: Long,
    val timestamp: String,
    val version: String,
    val manufacturer: String,
    val serialNumber: String,
    val orderId: String,
    val orderUpdateId: Long,
    val nodes: List<Node>,
    val edges: List<Edge>,
    val zoneSetId: String? = null,
)

@Serializable
data class Node(
    val nodeId: String,
    val sequenceId: Int,
    val released: Boolean,
    val actions: List<Action> = emptyList(),
    val nodePosition: NodePosition? = null,
    val nodeDescription: String? = null,
)

/** A node's position in metres and radians on the map [mapId]. */
@Serializable
data class NodePosition(
    val x: Double,
    val y: Double,
    val mapId: String,
    val theta: Double? = null,
    val allowedDeviationXY: Double? = null,
    val allowedDeviationTheta: Double? = null,
)

@Serializable
data class Edge(
    val edgeId: String,
    val sequenceId: Int,
    val released: Boolean,
    val startNodeId: String,
    val endNodeId: String,
    val actions: List<Action> = emptyList(),
    val maxSpeed: Double? = null,
    val length: Double? = null,
    val orientation: Double? = null,
    val rotationAllowed: Boolean? = null,
)

@Serializable
data class Action(
    val actionType: String,
    val actionId: String,
    val blockingType: String,
    val actionParameters: List<ActionParameter> = emptyList(),
    val actionDescription: String? = null,
)

@Serializable
data class ActionParameter(val key: String, val value: JsonElement)

/** An `instantActions` message (2.0 names the list `actions`). */
@Serializable
data class InstantActions(
    val headerId: Long,
    val timestamp: String,
    val version: String,
    val manufacturer: String,
    val serialNumber: String,
    val actions: List<Action>,
)

/** A `state` message: where the vehicle is and what it does. */
@Serializable
data class State(
    val headerId: Long,
    val timestamp: String,
    val version: String,
    val manufacturer: String,
    val serialNumber: String,
    val orderId: String,
    val orderUpdateId: Long,
    val lastNodeId: String,
    val lastNodeSequenceId: Int,
    val nodeStates: List<NodeState>,
    val edgeStates: List<EdgeState>,
    val driving: Boolean,
    val actionStates: List<ActionState>,
    val batteryState: BatteryState,
    val operatingMode: String,
    val errors: List<VehicleError>,
    val safetyState: SafetyState,
    val paused: Boolean? = null,
    val agvPosition: AgvPosition? = null,
    val loads: List<Load>? = null,
    val information: List<Information>? = null,
    val distanceSinceLastNode: Double? = null,
)

@Serializable
data class NodeState(val nodeId: String, val sequenceId: Int, val released: Boolean)

@Serializable
data class EdgeState(val edgeId: String, val sequenceId: Int, val released: Boolean)

@Serializable
data class ActionState(
    val actionId: String,
    val actionStatus: String,
    val actionType: String? = null,
    val resultDescription: String? = null,
)

@Serializable
data class BatteryState(val batteryCharge: Double, val charging: Boolean)

@Serializable
data class VehicleError(
    val errorType: String,
    val errorLevel: String,
    val errorDescription: String? = null,
    val errorReferences: List<Reference>? = null,
)

@Serializable
data class Information(val infoType: String, val infoLevel: String, val infoDescription: String? = null)

@Serializable
data class Reference(val referenceKey: String, val referenceValue: String)

@Serializable
data class SafetyState(val eStop: String, val fieldViolation: Boolean)

/** The vehicle's pose in metres and radians. */
@Serializable
data class AgvPosition(
    val x: Double,
    val y: Double,
    val theta: Double,
    val mapId: String,
    val positionInitialized: Boolean,
)

@Serializable
data class Load(val loadId: String? = null, val loadType: String? = null, val loadPosition: String? = null)

/** A `connection` message: ONLINE, OFFLINE or (the broker's last will) CONNECTIONBROKEN. */
@Serializable
data class Connection(
    val headerId: Long,
    val timestamp: String,
    val version: String,
    val manufacturer: String,
    val serialNumber: String,
    val connectionState: String,
)

/** A `visualization` message: the pose only, sent more often than `state`. */
@Serializable
data class Visualization(
    val headerId: Long,
    val timestamp: String,
    val version: String,
    val manufacturer: String,
    val serialNumber: String,
    val agvPosition: AgvPosition? = null,
)

/** Action and error names the driver relies on. */
object Vda {
    const val PROTOCOL_VERSION = "2.0.0"
    const val CANCEL_ORDER = "cancelOrder"
    const val START_PAUSE = "startPause"
    const val STOP_PAUSE = "stopPause"
    const val INIT_POSITION = "initPosition"
    const val STATE_REQUEST = "stateRequest"
    const val FACTSHEET_REQUEST = "factsheetRequest"
    const val START_CHARGING = "startCharging"
    const val PICK = "pick"
    const val DROP = "drop"
    const val FINISHED = "FINISHED"
    const val FAILED = "FAILED"
    const val FATAL = "FATAL"
    const val WARNING = "WARNING"
    const val ONLINE = "ONLINE"
    const val OFFLINE = "OFFLINE"
    const val CONNECTION_BROKEN = "CONNECTIONBROKEN"

    /** The errors with which a vehicle rejects an order (openTCS's list). */
    val REJECTIONS: Set<String> = setOf("validationError", "noRouteError", "orderError", "orderUpdateError")
}
