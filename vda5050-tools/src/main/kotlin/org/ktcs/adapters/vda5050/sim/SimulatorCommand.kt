package org.ktcs.adapters.vda5050.sim

import org.ktcs.adapters.vda5050.Vda5050Properties
import org.ktcs.adapters.vda5050.mqtt.BrokerSettings
import org.ktcs.api.model.PlantModel
import org.ktcs.api.model.PointType
import org.ktcs.kernel.app.PlantModelLoader
import org.ktcs.kernel.persistence.PlantModelFiles
import java.nio.file.Path
import java.util.concurrent.CountDownLatch
import java.util.concurrent.Executors
import kotlin.system.exitProcess

/** What `ktcs vda5050-sim` plays: which model's VDA 5050 vehicles, how many, over which broker, how fast. */
data class SimulatorOptions(
    val vehicles: Int? = null,
    val broker: String = "tcp://127.0.0.1:1883",
    val model: Path? = null,
    val timeFactor: Double = 1.0,
    val stateIntervalMillis: Long = 1000,
    val visualizationIntervalMillis: Long = 100,
) {
    companion object {
        const val USAGE = """usage: ktcs vda5050-sim [--vehicles N] [--broker URL] [--model FILE] [--time-factor F]
                         [--state-interval MS] [--visualization-interval MS]
  Plays the VDA 5050 vehicles of a plant model (default: the VDA 5050 demo plant) against an MQTT broker (default
  tcp://127.0.0.1:1883, kTCS's embedded broker), each starting on its vda5050:simulator.initialPosition (else its
  loopback:initialPosition, else a free park position). Stops on Ctrl-C, saying OFFLINE first."""

        fun parse(args: List<String>): SimulatorOptions {
            var options = SimulatorOptions()
            var i = 0
            fun value(): String = args.getOrNull(++i) ?: throw IllegalArgumentException("${args[i - 1]} needs a value")
            while (i < args.size) {
                options = when (val arg = args[i]) {
                    "--vehicles" -> options.copy(vehicles = value().toIntOrNull()?.takeIf { it > 0 } ?: bad(arg))

                    "--broker" -> options.copy(broker = value())

                    "--model" -> options.copy(model = Path.of(value()))

                    "--time-factor" -> options.copy(
                        timeFactor = value().toDoubleOrNull()?.takeIf {
                            it > 0
                        } ?: bad(arg),
                    )

                    "--state-interval" -> options.copy(
                        stateIntervalMillis = value().toLongOrNull()?.takeIf {
                            it > 0
                        } ?: bad(arg),
                    )

                    "--visualization-interval" ->
                        options.copy(
                            visualizationIntervalMillis = value().toLongOrNull()?.takeIf {
                                it > 0
                            } ?: bad(arg),
                        )

                    else -> throw IllegalArgumentException("unknown option '$arg'")
                }
                i++
            }
            return options
        }

        private fun bad(option: String): Nothing = throw IllegalArgumentException("$option needs a positive number")
    }
}

/** The VDA 5050 vehicles of [model] as the simulator plays them: at most [count], each with its start point. */
fun simulatedVehicles(model: PlantModel, options: SimulatorOptions): List<SimulatedVehicleSpec> {
    val vda = model.vehicles.filter { Vda5050Properties.VERSION in it.properties }
    require(vda.isNotEmpty()) { "the model '${model.name}' has no vehicle with vda5050:version" }
    val count = options.vehicles ?: vda.size
    require(count <= vda.size) { "the model '${model.name}' has ${vda.size} VDA 5050 vehicles, not $count" }
    val taken = mutableSetOf<String>()
    val parks = model.points.filter { it.type == PointType.PARK_POSITION }.map { it.name }
    return vda.take(count).map { vehicle ->
        val properties = Vda5050Properties.read(vehicle.name, vehicle.properties)
        val start = listOfNotNull(
            vehicle.properties["vda5050:simulator.initialPosition"],
            vehicle.properties["loopback:initialPosition"],
        ).firstOrNull { model.point(it) != null && it !in taken }
            ?: parks.firstOrNull { it !in taken }
            ?: model.points.map { it.name }.first { it !in taken }
        taken += start
        val position = model.point(start)!!.pose.position
        SimulatedVehicleSpec(
            manufacturer = properties.manufacturer,
            serialNumber = properties.serialNumber,
            topicPrefix = properties.topicPrefix,
            startNode = start,
            startX = position.x / MM_PER_M,
            startY = position.y / MM_PER_M,
            mapId = properties.mapId.orEmpty(),
            speedMetresPerSecond = vehicle.maxVelocity / MM_PER_M,
            stateIntervalMillis = options.stateIntervalMillis,
            visualizationIntervalMillis = options.visualizationIntervalMillis,
            timeFactor = options.timeFactor,
        )
    }
}

/** The VDA 5050 demo plant in this module's resources. */
fun vda5050DemoModel(): PlantModel = SimulatedVehicle::class.java.getResourceAsStream(DEMO)!!.use {
    PlantModelFiles.read(it, "VDA 5050 demo plant")
}

private const val DEMO = "/org/ktcs/adapters/vda5050/demo/vda5050-demo.xml"
private const val MM_PER_M = 1000.0

/** `ktcs vda5050-sim`: plays the vehicles until the process is stopped. */
fun main(args: Array<String>) {
    if ("--help" in args || "-h" in args) {
        println(SimulatorOptions.USAGE)
        return
    }
    val options = try {
        SimulatorOptions.parse(args.toList())
    } catch (error: IllegalArgumentException) {
        System.err.println("ktcs vda5050-sim: ${error.message}\n${SimulatorOptions.USAGE}")
        exitProcess(2)
    }
    val vehicles = try {
        val model = options.model?.let { PlantModelLoader.load(it).model } ?: vda5050DemoModel()
        val endpoint = BrokerSettings(url = options.broker).endpoint()
        val executor = Executors.newScheduledThreadPool(2) { Thread(it, "vda5050-sim").apply { isDaemon = true } }
        simulatedVehicles(model, options).map { SimulatedVehicle(it, endpoint, executor) }
            .also { println("ktcs vda5050-sim: ${it.size} vehicles against $endpoint") }
    } catch (error: IllegalArgumentException) {
        System.err.println("ktcs vda5050-sim: ${error.message}")
        exitProcess(1)
    }
    vehicles.forEach { it.start() }
    println("ktcs vda5050-sim: playing ${vehicles.joinToString { it.spec.serialNumber }}")
    val stopped = CountDownLatch(1)
    Runtime.getRuntime().addShutdownHook(
        Thread {
            vehicles.forEach { runCatching { it.close() } }
            stopped.countDown()
        },
    )
    stopped.await()
}
