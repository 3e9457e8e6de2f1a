package org.ktcs.examples.tcpdriver

import org.ktcs.api.driver.DriverContext
import org.ktcs.api.driver.VehicleDriver
import org.ktcs.api.driver.VehicleDriverFactory
import java.net.InetSocketAddress

// snippet:driver-factory
/**
 * Creates [TcpVehicleDriver]s for the vehicles whose properties say where they listen: `tcp:port` (required),
 * `tcp:host` (default 127.0.0.1) and `tcp:commandQueueCapacity` (default 2).
 */
class TcpVehicleDriverFactory : VehicleDriverFactory {
    override val name: String = NAME

    override val description: String = "Vehicle speaking the example line protocol over TCP"

    override fun canDrive(vehicleName: String, context: DriverContext): Boolean =
        PORT in context.vehicle().properties

    override fun create(vehicleName: String, context: DriverContext): VehicleDriver {
        val properties = context.vehicle().properties
        val port = properties[PORT]?.toIntOrNull()?.takeIf { it in 1..MAX_PORT }
            ?: throw IllegalArgumentException(
                "vehicle $vehicleName: $PORT must be a TCP port, was '${properties[PORT]}'",
            )
        val capacity = properties[CAPACITY]?.let {
            it.toIntOrNull()?.takeIf { value -> value > 0 }
                ?: throw IllegalArgumentException("vehicle $vehicleName: $CAPACITY must be positive, was '$it'")
        } ?: DEFAULT_CAPACITY
        val address = InetSocketAddress(properties[HOST] ?: DEFAULT_HOST, port)
        return TcpVehicleDriver(vehicleName, context, address, capacity)
    }

    companion object {
        /** The name to use in the vehicle property `tcs:preferredAdapterClass`. */
        const val NAME = "tcp-line"
        const val HOST = "tcp:host"
        const val PORT = "tcp:port"
        const val CAPACITY = "tcp:commandQueueCapacity"
        private const val DEFAULT_HOST = "127.0.0.1"
        private const val DEFAULT_CAPACITY = 2
        private const val MAX_PORT = 65535
    }
}
// end-snippet
