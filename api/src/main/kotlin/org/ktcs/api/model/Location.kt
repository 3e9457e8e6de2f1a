package org.ktcs.api.model

/**
 * A station where vehicles perform operations (load, unload, charge, …), reached through linked points.
 *
 * @property locked vehicles are not sent to a locked location.
 */
public data class Location(
    override val name: String,
    val type: String,
    val position: Position = Position(0, 0, 0),
    val links: List<Link> = emptyList(),
    val locked: Boolean = false,
    val layout: LocationLayout = LocationLayout(),
    override val properties: Map<String, String> = emptyMap(),
) : PlantObject

/**
 * Connects a location to a point from which vehicles operate at it.
 *
 * @property allowedOperations operations allowed through this link; empty means all operations of the location type.
 */
public data class Link(val point: String, val allowedOperations: Set<String> = emptySet())

/** How a location is drawn. */
public data class LocationLayout(
    val labelOffset: Couple = Couple(-10, -20),
    val locationRepresentation: LocationRepresentation = LocationRepresentation.DEFAULT,
    val layerId: Int = 0,
)

/** The kind of a location: which operations vehicles and peripherals may perform there. */
public data class LocationType(
    override val name: String,
    val allowedOperations: Set<String> = emptySet(),
    val allowedPeripheralOperations: Set<String> = emptySet(),
    val layout: LocationTypeLayout = LocationTypeLayout(),
    override val properties: Map<String, String> = emptyMap(),
) : PlantObject

/** How locations of a type are drawn unless they say otherwise. */
public data class LocationTypeLayout(val locationRepresentation: LocationRepresentation = LocationRepresentation.NONE)

/** The symbol of a location or location type. */
public enum class LocationRepresentation {
    NONE,
    DEFAULT,
    LOAD_TRANSFER_GENERIC,
    LOAD_TRANSFER_ALT_1,
    LOAD_TRANSFER_ALT_2,
    LOAD_TRANSFER_ALT_3,
    LOAD_TRANSFER_ALT_4,
    LOAD_TRANSFER_ALT_5,
    WORKING_GENERIC,
    WORKING_ALT_1,
    WORKING_ALT_2,
    RECHARGE_GENERIC,
    RECHARGE_ALT_1,
    RECHARGE_ALT_2,
}
