package org.ktcs.adapters.vda5050

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import org.ktcs.api.driver.DriverContext
import org.ktcs.api.driver.MovementCommand
import org.ktcs.api.event.NotificationLevel
import org.ktcs.api.kernel.Cancellable
import org.ktcs.api.kernel.KernelClock
import org.ktcs.api.model.LoadHandlingDevice
import org.ktcs.api.model.PlantModel
import org.ktcs.api.model.Position
import org.ktcs.api.model.Vehicle
import org.ktcs.api.model.VehicleState
import java.time.Instant

/** A driver context that queues the kernel tasks a driver schedules and records the poses it reports. */
private class PoseRecordingContext : DriverContext {
    val kernelTasks = ArrayDeque<() -> Unit>()
    val poses = mutableListOf<Pair<Position?, Double>>()

    fun runKernel() {
        while (kernelTasks.isNotEmpty()) kernelTasks.removeFirst()()
    }

    override val clock = object : KernelClock {
        override fun now(): Instant = Instant.EPOCH

        override fun elapsedMillis(): Long = 0

        override fun schedule(delayMillis: Long, action: () -> Unit): Cancellable {
            kernelTasks.addLast(action)
            return Cancellable { }
        }
    }
    override val plantModel = PlantModel("test")

    override fun vehicle() = Vehicle("Vehicle-01")

    override fun vehiclePositions(): Map<String, String> = emptyMap()

    override fun reportPrecisePosition(position: Position?, orientationAngle: Double) {
        poses += position to orientationAngle
    }

    override fun reportPosition(point: String?) = Unit

    override fun reportState(state: VehicleState) = Unit

    override fun reportEnergyLevel(percent: Int) = Unit

    override fun reportLoadHandlingDevices(devices: List<LoadHandlingDevice>) = Unit

    override fun commandExecuted(command: MovementCommand) = Unit

    override fun commandFailed(command: MovementCommand) = Unit

    override fun reportLength(length: Long) = Unit

    override fun setVehicleProperty(key: String, value: String?) = Unit

    override fun setTransportOrderProperty(key: String, value: String?) = Unit

    override fun publishEvent(type: String, payload: Map<String, String>) = Unit

    override fun notifyUser(level: NotificationLevel, text: String) = Unit
}

/**
 * A vehicle's poses reach the kernel only when they change what the kernel shows (millimetres, a tenth of a degree):
 * a vehicle standing still sends its pose three times a second (state and visualization), which must cost no kernel
 * task.
 */
class VehicleReportsTest : FunSpec({
    fun reports(context: DriverContext) =
        VehicleReports("Vehicle-01", context, Vda5050Properties.read("Vehicle-01", vdaProperties("SIM-1")))

    test("a pose that changes nothing the kernel shows schedules no kernel task") {
        val context = PoseRecordingContext()
        val reports = reports(context)
        reports.pose(1.0, 2.0, Math.PI / 2)
        context.kernelTasks.size shouldBe 1
        context.runKernel()
        context.poses shouldBe listOf(Position(1000, 2000) to 90.0)

        reports.pose(1.0, 2.0, Math.PI / 2) // standing still
        reports.pose(1.0004, 2.0002, Math.PI / 2 + 1e-5) // jitter below a millimetre and a tenth of a degree
        context.kernelTasks.size shouldBe 0

        reports.pose(1.25, 2.0, Math.PI / 2)
        reports.pose(1.5, 2.0, Math.PI)
        context.kernelTasks.size shouldBe 1 // coalesced: the kernel reports the latest
        context.runKernel()
        context.poses.last() shouldBe (Position(1500, 2000) to 180.0)
        context.poses.size shouldBe 2
    }

    test("after a reset the same pose is reported again") {
        val context = PoseRecordingContext()
        val reports = reports(context)
        reports.pose(3.0, 4.0, 0.0)
        context.runKernel()
        reports.reset()
        reports.pose(3.0, 4.0, 0.0)
        context.runKernel()
        context.poses shouldBe listOf(Position(3000, 4000) to 0.0, Position(3000, 4000) to 0.0)
    }
})
