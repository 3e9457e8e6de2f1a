package org.ktcs.adapters.loopback

import org.ktcs.api.driver.DriverMessage
import org.ktcs.api.driver.MovementCommand
import org.ktcs.api.model.Location
import org.ktcs.api.model.Path
import org.ktcs.api.model.PlantModel
import org.ktcs.api.model.Point
import org.ktcs.api.model.Pose
import org.ktcs.api.model.Position
import org.ktcs.api.model.Vehicle
import org.ktcs.api.model.VehicleState
import org.ktcs.api.order.Step
import org.ktcs.api.order.VehicleOrientation

/**
 * A small plant: A(0,0) -10 m-> B(10 m,0) -10 m-> C(10 m,10 m), B -1 km-> E(1010 m,0), a slow path A -1 m-> S,
 * stations at B ("Station") and C ("Charger"), and vehicle V (1000 mm/s forward, 400 mm/s backward) starting at A.
 */
object LoopbackFixtures {
    const val VEHICLE = "V"

    fun point(name: String, x: Long, y: Long) = Point(name, Pose(Position(x, y)))

    fun plant(vehicle: Vehicle = vehicle()) = PlantModel(
        name = "loopback-test",
        points = listOf(
            point("A", 0, 0),
            point("B", 10_000, 0),
            point("C", 10_000, 10_000),
            point("E", 1_010_000, 0),
            point("S", 0, 1_000),
        ),
        paths = listOf(
            Path("A--B", "A", "B", length = 10_000, maxVelocity = 1000, maxReverseVelocity = 500),
            Path("B--C", "B", "C", length = 10_000, maxVelocity = 1000),
            Path("B--E", "B", "E", length = 1_000_000, maxVelocity = 1000),
            Path("A--S", "A", "S", length = 1_000, maxVelocity = 0),
        ),
        locations = listOf(Location("Station", "Transfer"), Location("Charger", "Recharge")),
        vehicles = listOf(vehicle),
    )

    fun vehicle(vararg properties: Pair<String, String>, energy: Int = 100) = Vehicle(
        name = VEHICLE,
        maxVelocity = 1000,
        maxReverseVelocity = 400,
        energyLevel = energy,
        properties = mapOf(LoopbackProperties.INITIAL_POSITION to "A") + properties,
    )

    /** A command driving [path] from [from] to [to], then performing [operation] at [location] if given. */
    fun command(
        path: String?,
        from: String?,
        to: String,
        operation: String = MovementCommand.NO_OPERATION,
        location: String? = null,
        orientation: VehicleOrientation = VehicleOrientation.FORWARD,
        order: String = "T1",
    ) = MovementCommand(
        transportOrder = order,
        driveOrder = "$order-1",
        step = Step(path, from, to, orientation),
        operation = operation,
        opLocation = location,
        finalMovement = true,
        finalDestination = to,
        finalDestinationLocation = location,
        finalOperation = operation,
    )

    val aToB = command("A--B", "A", "B")
    val bToC = command("B--C", "B", "C")
    val bToE = command("B--E", "B", "E")
}

/** A fresh loopback driver for vehicle V on [LoopbackFixtures.plant], enabled unless told otherwise. */
class Harness(
    settings: LoopbackSettings = LoopbackSettings(positionReportIntervalMillis = 0),
    vehicle: Vehicle = LoopbackFixtures.vehicle(),
    enable: Boolean = true,
) {
    val context = FakeDriverContext(LoopbackFixtures.plant(vehicle), LoopbackFixtures.VEHICLE)
    val clock: VirtualClock get() = context.clock
    val driver = LoopbackDriver(LoopbackFixtures.VEHICLE, context, settings)

    init {
        if (enable) driver.enable()
    }

    fun send(vararg commands: MovementCommand) = commands.forEach { check(driver.enqueueCommand(it)) { "refused $it" } }

    fun message(type: String, vararg parameters: Pair<String, String>) =
        driver.processMessage(DriverMessage(type, mapOf(*parameters)))

    fun executedAt(): List<Long> = context.timesOf<Report.Executed>()

    fun states(): List<VehicleState> = context.reportsOf<Report.State>().map { it.state }

    fun energies(): List<Int> = context.reportsOf<Report.Energy>().map { it.percent }

    fun notifications(): List<String> = context.reportsOf<Report.Notification>().map { it.text }
}
