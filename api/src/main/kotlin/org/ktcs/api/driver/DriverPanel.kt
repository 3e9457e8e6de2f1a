package org.ktcs.api.driver

/**
 * A driver's panel in the browser overview's vehicle details (openTCS's comm adapter panel), shown for every vehicle
 * that a driver of the declaring [VehicleDriverFactory] drives, and the [commands] the panel may send to the driver.
 *
 * The overview serves the class-path files under [resourceDirectory], as seen by [classLoader], at
 * `/overview/drivers/{driver}/` and imports [entryModule] from there; its default export has
 * `mount(container, ktcs, vehicle)` (the contract is in `web-overview/README.md`). The kernel checks every command
 * against its [DriverCommand] before the driver sees it, so a driver only ever gets well-formed parameters.
 */
public class DriverPanel(
    /** What the overview shows as the panel's heading, e.g. "Loopback (simulated vehicle)". */
    public val title: String,
    /** The class-path directory holding the front-end files, e.g. `org/example/driver/panel`. */
    public val resourceDirectory: String,
    /** The class loader that sees [resourceDirectory]; pass the driver's own (`javaClass.classLoader`). */
    public val classLoader: ClassLoader,
    /** The commands a client may send to the driver of one vehicle through the panel or the web API. */
    public val commands: List<DriverCommand> = emptyList(),
    /** The ES module inside [resourceDirectory] that the overview imports. */
    public val entryModule: String = "panel.js",
) {
    init {
        require(title.isNotBlank()) { "a driver panel needs a title" }
        require(!entryModule.startsWith("/") && ".." !in entryModule) {
            "entry module '$entryModule' of driver panel '$title' must be a path inside its resource directory"
        }
        val duplicates = commands.groupBy { it.name }.filterValues { it.size > 1 }.keys
        require(duplicates.isEmpty()) { "driver panel '$title' declares commands twice: ${duplicates.joinToString()}" }
    }

    /** The command named [name], or `null`. */
    public fun command(name: String): DriverCommand? = commands.firstOrNull { it.name == name }
}

/**
 * A command a driver accepts from its panel: the kernel delivers it to [VehicleDriver.processMessage] as a
 * [DriverMessage] of type [name] once every parameter passed its [DriverParameter] check; parameters not declared
 * are refused.
 */
public data class DriverCommand(
    /** The message type the driver receives, e.g. `tcs:virtualVehicle:setEnergyLevel`. */
    val name: String,
    /** What the command does, for the API document and the panel's tooltips. */
    val description: String,
    val parameters: List<DriverParameter> = emptyList(),
) {
    init {
        require(name.isNotBlank()) { "a driver command needs a name" }
        val duplicates = parameters.groupBy { it.name }.filterValues { it.size > 1 }.keys
        require(duplicates.isEmpty()) {
            "driver command '$name' declares parameters twice: ${duplicates.joinToString()}"
        }
    }
}

/**
 * One parameter of a [DriverCommand].
 *
 * @property values for [ParameterType.CHOICE]: the allowed values (compared ignoring case, delivered as listed).
 * @property min for [ParameterType.INTEGER] and [ParameterType.NUMBER]: the smallest allowed value.
 * @property max for [ParameterType.INTEGER] and [ParameterType.NUMBER]: the largest allowed value.
 */
public data class DriverParameter(
    val name: String,
    val type: ParameterType,
    val description: String = "",
    val required: Boolean = true,
    val values: List<String> = emptyList(),
    val min: Double? = null,
    val max: Double? = null,
) {
    init {
        require(type != ParameterType.CHOICE || values.isNotEmpty()) { "choice parameter '$name' needs values" }
        require(min == null || max == null || min <= max) { "parameter '$name': min $min is above max $max" }
    }
}

/** What a [DriverParameter] holds; the kernel checks a value's form (and for [POINT] that the point exists). */
public enum class ParameterType {
    /** Any text. */
    TEXT,

    /** A whole number. */
    INTEGER,

    /** A finite number. */
    NUMBER,

    /** `true` or `false`. */
    BOOLEAN,

    /** One of the parameter's values. */
    CHOICE,

    /** The name of a point of the plant model. */
    POINT,
}

/**
 * What the overview shows in a vehicle's driver panel: the driver's own state ([VehicleDriver.panelState]) and the
 * vehicle's command queue as the kernel sees it.
 *
 * @property driver the name of the factory whose driver drives the vehicle.
 * @property panel the panel, `null` if that driver has none.
 * @property state the driver's state for its panel, e.g. `singleStepMode=true`.
 * @property commandQueue the commands of the vehicle's current order, oldest first.
 */
public data class DriverPanelView(
    val vehicle: String,
    val driver: String,
    val driverEnabled: Boolean,
    val panel: DriverPanel?,
    val state: Map<String, String>,
    val commandQueue: List<QueuedCommand>,
)

/** One movement command in a vehicle's queue and how far it got. */
public data class QueuedCommand(val command: MovementCommand, val stage: CommandStage)

/** How far a [QueuedCommand] got. */
public enum class CommandStage {
    /** Sent to the driver, not reported executed yet; the first one is the one being carried out. */
    SENT,

    /** Its resources were asked for and are not granted yet. */
    WAITING_FOR_RESOURCES,

    /** Planned, not yet asked for. */
    QUEUED,
}
