package org.ktcs.examples.tcpdriver

import org.ktcs.api.driver.BasicVehicleDriver
import org.ktcs.api.driver.DriverContext
import org.ktcs.api.driver.DriverMessage
import org.ktcs.api.driver.MovementCommand
import org.ktcs.api.event.NotificationLevel
import org.ktcs.api.kernel.Explained
import org.ktcs.api.model.VehicleState
import org.ktcs.api.order.TransportOrder
import org.slf4j.LoggerFactory
import java.net.InetSocketAddress

/**
 * Drives a vehicle that speaks [LineProtocol] over TCP. [BasicVehicleDriver] keeps at most
 * `commandQueueCapacity` commands at the vehicle; this class numbers them, sends them and reports what the vehicle
 * says. Lines arrive on the connection's thread: reports go straight to the [DriverContext] (safe from any thread),
 * while the command bookkeeping runs in the kernel context through `context.clock.schedule(0)`.
 */
class TcpVehicleDriver(
    vehicleName: String,
    context: DriverContext,
    address: InetSocketAddress,
    commandQueueCapacity: Int,
) : BasicVehicleDriver(vehicleName, context, commandQueueCapacity) {
    private val log = LoggerFactory.getLogger(TcpVehicleDriver::class.java)
    private val connection = VehicleConnection(vehicleName, address, Reports())
    private val commandsById = mutableMapOf<Long, MovementCommand>()
    private var nextId = 1L

    // snippet:driver-send-command
    override fun sendCommand(command: MovementCommand) {
        val id = nextId++
        commandsById[id] = command
        connection.send(LineProtocol.command(id, command.step.destinationPoint, command.operation, command.opLocation))
    }
    // end-snippet

    override fun onEnabled() = connection.open()

    override fun onDisabled() {
        connection.close()
        commandsById.clear()
    }

    override fun onCommandQueueCleared() {
        commandsById.clear()
        connection.send(LineProtocol.clear())
    }

    // snippet:driver-veto
    override fun canProcess(order: TransportOrder): Explained = if (connection.isConnected) {
        Explained.YES
    } else {
        Explained.no("vehicle $vehicleName is not connected")
    }
    // end-snippet

    // snippet:driver-message
    override fun processMessage(message: DriverMessage) {
        connection.send(LineProtocol.message(message.type, message.parameters))
    }
    // end-snippet

    override fun onPaused(paused: Boolean) = connection.send(LineProtocol.pause(paused))

    /** Runs [action] on the command bookkeeping in the kernel context. */
    private fun inKernelContext(action: () -> Unit) = context.clock.schedule(0, action)

    private inner class Reports : VehicleConnection.Listener {
        override fun connected() {
            log.info("vehicle {} connected", vehicleName)
            // After a dropped connection the kernel has failed the commands it had sent; the vehicle must drop them too.
            connection.send(LineProtocol.clear())
        }

        override fun disconnected(reason: String) {
            context.reportState(VehicleState.UNKNOWN)
            context.notifyUser(NotificationLevel.IMPORTANT, "vehicle $vehicleName lost its connection: $reason")
            // The vehicle may have lost what it was told: its commands fail, so the kernel withdraws the order.
            inKernelContext {
                val lost = commandsById.values.toList()
                commandsById.clear()
                lost.forEach(::onCommandFailed)
            }
        }

        // snippet:driver-reports
        override fun received(line: String) {
            val message = LineProtocol.parse(line)
            val fields = message.fields
            try {
                when (message.name) {
                    "POSITION" -> context.reportPosition(fields.single().ifEmpty { null })
                    "ENERGY" -> context.reportEnergyLevel(fields.single().toInt())
                    "STATE" -> context.reportState(VehicleState.valueOf(fields.single()))
                    "EXECUTED" -> finished(fields.single().toLong(), failed = false)
                    "FAILED" -> finished(fields.single().toLong(), failed = true)
                    "PROPERTY" -> context.setVehicleProperty(fields[0], fields[1].ifEmpty { null })
                    "EVENT" -> context.publishEvent(fields[0], LineProtocol.parameters(fields.drop(1)))
                    else -> log.warn("vehicle {} sent an unknown message: {}", vehicleName, line)
                }
            } catch (error: IllegalArgumentException) {
                log.warn("vehicle {} sent a malformed message '{}': {}", vehicleName, line, error.message)
            } catch (error: IndexOutOfBoundsException) {
                log.warn("vehicle {} sent a message with missing fields: {}", vehicleName, line)
            }
        }
        // end-snippet

        private fun finished(id: Long, failed: Boolean) = inKernelContext {
            val command = commandsById.remove(id) ?: return@inKernelContext
            if (failed) onCommandFailed(command) else onCommandExecuted(command)
        }
    }
}
