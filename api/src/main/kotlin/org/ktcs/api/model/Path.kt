package org.ktcs.api.model

/**
 * A directed connection between two points that vehicles drive along.
 *
 * @property length millimetres.
 * @property maxVelocity mm/s when driving forward; 0 means vehicles may not drive this path forward.
 * @property maxReverseVelocity mm/s when driving backward (destination to source); 0 means not at all.
 * @property locked a locked path is never used by the router.
 */
public data class Path(
    override val name: String,
    val sourcePoint: String,
    val destinationPoint: String,
    val length: Long = 1,
    val maxVelocity: Int = 1000,
    val maxReverseVelocity: Int = 0,
    val peripheralOperations: List<PeripheralOperation> = emptyList(),
    val locked: Boolean = false,
    val vehicleEnvelopes: Map<String, Envelope> = emptyMap(),
    val layout: PathLayout = PathLayout(),
    override val properties: Map<String, String> = emptyMap(),
) : PlantObject {
    /** Whether vehicles may drive from [sourcePoint] to [destinationPoint]. */
    val isNavigableForward: Boolean get() = maxVelocity != 0

    /** Whether vehicles may drive from [destinationPoint] to [sourcePoint]. */
    val isNavigableReverse: Boolean get() = maxReverseVelocity != 0
}

/** An operation a peripheral device at [location] performs when a vehicle uses a path. */
public data class PeripheralOperation(
    val operation: String,
    val location: String,
    val executionTrigger: ExecutionTrigger = ExecutionTrigger.AFTER_ALLOCATION,
    val completionRequired: Boolean = false,
)

/** When a path's peripheral operation is carried out. */
public enum class ExecutionTrigger {
    /** As soon as the path is allocated to a vehicle (openTCS before 6.0 called it BEFORE_MOVEMENT). */
    AFTER_ALLOCATION,

    /** When the vehicle has driven the path. */
    AFTER_MOVEMENT,
}

/** How a path is drawn. */
public data class PathLayout(
    val connectionType: ConnectionType = ConnectionType.DIRECT,
    val controlPoints: List<Couple> = emptyList(),
    val layerId: Int = 0,
)

/** The shape of a drawn path. */
public enum class ConnectionType { DIRECT, ELBOW, SLANTED, POLYPATH, BEZIER, BEZIER_3 }
