package org.ktcs.kernel.web.v1.drivers

import kotlinx.serialization.Serializable
import org.ktcs.api.driver.DriverCommand
import org.ktcs.api.driver.DriverPanelView
import org.ktcs.api.driver.QueuedCommand
import org.ktcs.api.event.DriverEvent
import org.ktcs.kernel.web.v1.toWire

/** `GET /vehicles/{NAME}/driverPanel`: the vehicle's driver, its panel (if any), its state and the command queue. */
@Serializable
data class DriverPanelDto(
    val vehicle: String,
    val driver: String,
    val driverEnabled: Boolean,
    val panel: PanelDto?,
    val state: Map<String, String>,
    val commandQueue: List<QueuedCommandDto>,
)

/** [module] is the panel's entry module, served by the overview at `/overview/drivers/{driver}/{module}`. */
@Serializable
data class PanelDto(val title: String, val module: String, val commands: List<DriverCommandDto>)

@Serializable
data class DriverCommandDto(val name: String, val description: String, val parameters: List<DriverParameterDto>)

@Serializable
data class DriverParameterDto(
    val name: String,
    val type: String,
    val description: String,
    val required: Boolean,
    val values: List<String>,
    val min: Double?,
    val max: Double?,
)

/** One movement command: [stage] is SENT, WAITING_FOR_RESOURCES or QUEUED. */
@Serializable
data class QueuedCommandDto(
    val transportOrder: String,
    val driveOrder: String,
    val stage: String,
    val path: String?,
    val sourcePoint: String?,
    val destinationPoint: String,
    val operation: String,
    val location: String?,
)

/** The body of `POST /vehicles/{NAME}/driverCommand`. */
@Serializable
data class PostDriverCommandRequest(
    val driver: String? = null,
    val command: String? = null,
    val parameters: Map<String, String> = emptyMap(),
)

/** A driver event as the web API, the WebSocket topic `driverEvents` and the SSE stream carry it. */
@Serializable
data class DriverEventDto(
    val vehicle: String,
    val type: String,
    val payload: Map<String, String>,
    val timestamp: String,
)

fun DriverPanelView.toDto() = DriverPanelDto(
    vehicle = vehicle,
    driver = driver,
    driverEnabled = driverEnabled,
    panel = panel?.let { PanelDto(it.title, it.entryModule, it.commands.map(DriverCommand::toDto)) },
    state = state,
    commandQueue = commandQueue.map(QueuedCommand::toDto),
)

private fun DriverCommand.toDto() = DriverCommandDto(
    name,
    description,
    parameters.map {
        DriverParameterDto(it.name, it.type.name, it.description, it.required, it.values, it.min, it.max)
    },
)

private fun QueuedCommand.toDto() = QueuedCommandDto(
    transportOrder = command.transportOrder,
    driveOrder = command.driveOrder,
    stage = stage.name,
    path = command.step.path,
    sourcePoint = command.step.sourcePoint,
    destinationPoint = command.step.destinationPoint,
    operation = command.operation,
    location = command.opLocation,
)

fun DriverEvent.toDto() = DriverEventDto(vehicle, type, payload, timestamp.toWire())
