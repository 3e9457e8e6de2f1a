package org.ktcs.api.model

/**
 * A whole plant: the roadmap, the stations, the vehicles and how to draw them. An immutable snapshot.
 *
 * Lists keep the order of the model file, so writing a model back reproduces it. Lookups by name are built on
 * first use.
 */
public data class PlantModel(
    val name: String,
    val points: List<Point> = emptyList(),
    val paths: List<Path> = emptyList(),
    val vehicles: List<Vehicle> = emptyList(),
    val locationTypes: List<LocationType> = emptyList(),
    val locations: List<Location> = emptyList(),
    val blocks: List<Block> = emptyList(),
    val visualLayout: VisualLayout = VisualLayout(),
    val properties: Map<String, String> = emptyMap(),
) {
    private val pointsByName by lazy { points.associateBy { it.name } }
    private val pathsByName by lazy { paths.associateBy { it.name } }
    private val vehiclesByName by lazy { vehicles.associateBy { it.name } }
    private val locationTypesByName by lazy { locationTypes.associateBy { it.name } }
    private val locationsByName by lazy { locations.associateBy { it.name } }
    private val blocksByName by lazy { blocks.associateBy { it.name } }
    private val outgoing by lazy { paths.groupBy { it.sourcePoint } }
    private val incoming by lazy { paths.groupBy { it.destinationPoint } }

    /** The point named [name], or `null`. */
    public fun point(name: String): Point? = pointsByName[name]

    /** The path named [name], or `null`. */
    public fun path(name: String): Path? = pathsByName[name]

    /** The vehicle named [name], or `null`. */
    public fun vehicle(name: String): Vehicle? = vehiclesByName[name]

    /** The location type named [name], or `null`. */
    public fun locationType(name: String): LocationType? = locationTypesByName[name]

    /** The location named [name], or `null`. */
    public fun location(name: String): Location? = locationsByName[name]

    /** The block named [name], or `null`. */
    public fun block(name: String): Block? = blocksByName[name]

    /** The object of any kind named [name], or `null`. */
    public fun objectNamed(name: String): PlantObject? =
        point(name) ?: path(name) ?: location(name) ?: locationType(name) ?: vehicle(name) ?: block(name)

    /** Paths that start at the point named [point], in model order. */
    public fun outgoingPaths(point: String): List<Path> = outgoing[point].orEmpty()

    /** Paths that end at the point named [point], in model order. */
    public fun incomingPaths(point: String): List<Path> = incoming[point].orEmpty()

    /** Every object of the model, points first, in the order of the model file. */
    public fun allObjects(): Sequence<PlantObject> =
        points.asSequence() + paths + vehicles + locationTypes + locations + blocks

    /** Counts per kind, as `points=N paths=N locations=N locationTypes=N blocks=N vehicles=N`. */
    public fun summary(): String = "points=${points.size} paths=${paths.size} locations=${locations.size} " +
        "locationTypes=${locationTypes.size} blocks=${blocks.size} vehicles=${vehicles.size}"
}
