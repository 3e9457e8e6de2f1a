package org.ktcs.examples.tcpdriver

import java.io.BufferedWriter
import java.io.IOException
import java.net.InetAddress
import java.net.ServerSocket
import java.net.Socket
import java.util.concurrent.LinkedBlockingDeque
import kotlin.concurrent.thread

/**
 * A vehicle that speaks [LineProtocol], for trying the driver without hardware: it listens on [port] (0: any free
 * one), drives to each commanded point in [travelMillis], operates in [operationMillis], uses one percent of energy
 * per command and recharges to 100 on the operation "CHARGE". A message `MESSAGE|type|...` becomes the vehicle
 * property `tcp:lastMessage` and an event `messageReceived`. One kTCS connection at a time.
 */
class LineVehicleSimulator(
    private val initialPosition: String,
    port: Int = 0,
    private val travelMillis: Long = 200,
    private val operationMillis: Long = 100,
) : AutoCloseable {
    private val server = ServerSocket(port, 1, InetAddress.getLoopbackAddress())
    private val commands = LinkedBlockingDeque<List<String>>()

    @Volatile private var out: BufferedWriter? = null

    @Volatile private var position = initialPosition

    @Volatile private var energy = 100

    @Volatile private var closed = false

    /** How many commands the simulated vehicle carried out. */
    @Volatile var executed = 0
        private set

    val port: Int get() = server.localPort

    private val acceptor = thread(name = "line-vehicle-simulator", isDaemon = true) { acceptWhileOpen() }
    private val worker = thread(name = "line-vehicle-worker", isDaemon = true) { workWhileOpen() }

    override fun close() {
        closed = true
        server.close()
        acceptor.interrupt()
        worker.interrupt()
    }

    private fun acceptWhileOpen() {
        while (!closed) {
            try {
                server.accept().use(::serve)
            } catch (_: IOException) {
                // The connection ended or the simulator was closed.
            }
        }
    }

    private fun serve(socket: Socket) {
        out = socket.getOutputStream().bufferedWriter()
        send(LineProtocol.position(position), LineProtocol.energy(energy), LineProtocol.state("IDLE"))
        try {
            socket.getInputStream().bufferedReader().lineSequence().forEach(::handle)
        } finally {
            out = null
            commands.clear()
        }
    }

    // A malformed line is ignored: it must not end the connection or the simulator.
    private fun handle(line: String) {
        val message = runCatching { LineProtocol.parse(line) }.getOrNull() ?: return
        when (message.name) {
            "COMMAND" -> if (message.fields.size >= COMMAND_FIELDS && message.fields[0].toLongOrNull() != null) {
                commands.put(message.fields)
            }

            "CLEAR" -> commands.clear()

            "MESSAGE" -> message.fields.firstOrNull()?.let { type ->
                send(
                    LineProtocol.property("tcp:lastMessage", type),
                    LineProtocol.event("messageReceived", mapOf("type" to type)),
                )
            }
        }
    }

    private fun workWhileOpen() {
        try {
            while (!closed) execute(commands.take())
        } catch (_: InterruptedException) {
            // Closed.
        }
    }

    private fun execute(fields: List<String>) {
        val (id, point, operation) = fields
        send(LineProtocol.state("EXECUTING"))
        Thread.sleep(travelMillis)
        position = point
        energy = (energy - 1).coerceAtLeast(0)
        send(LineProtocol.position(point), LineProtocol.energy(energy))
        if (operation != "NOP" && operation != "MOVE" && operation != "PARK") Thread.sleep(operationMillis)
        if (operation == "CHARGE") energy = 100
        executed++
        send(LineProtocol.energy(energy), LineProtocol.executed(id.toLong()))
        if (commands.isEmpty()) send(LineProtocol.state("IDLE"))
    }

    private fun send(vararg lines: String) {
        val writer = out ?: return
        try {
            synchronized(writer) {
                lines.forEach { writer.write(it + "\n") }
                writer.flush()
            }
        } catch (_: IOException) {
            // kTCS went away; it reconnects and gets the current position then.
        }
    }
}

/** Runs the simulator: `LineVehicleSimulator POSITION [PORT]`, e.g. `Point-0027 7001`. */
fun main(args: Array<String>) {
    require(args.isNotEmpty()) { "usage: LineVehicleSimulator POSITION [PORT]" }
    val simulator = LineVehicleSimulator(args[0], args.getOrNull(1)?.toInt() ?: 0)
    println("line vehicle simulator at ${args[0]} listening on port ${simulator.port}")
    Thread.currentThread().join()
}

private const val COMMAND_FIELDS = 3
