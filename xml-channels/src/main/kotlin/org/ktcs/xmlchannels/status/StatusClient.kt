package org.ktcs.xmlchannels.status

import kotlinx.coroutines.channels.Channel
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.launch
import java.io.IOException
import java.net.Socket
import java.net.SocketAddress

/**
 * One status channel client: a bounded queue of documents and the socket they are written to. Whatever the client
 * sends is read and thrown away, which also notices when it hangs up.
 */
internal class StatusClient(private val socket: Socket, capacity: Int) {
    private val outbox = Channel<ByteArray>(capacity)

    val address: SocketAddress? get() = socket.remoteSocketAddress

    /** Queues [document]; `false` only if the queue is full, i.e. the client does not keep up. */
    fun offer(document: ByteArray): Boolean = outbox.trySend(document).let { it.isSuccess || it.isClosed }

    /** Writes queued documents until the client hangs up or is closed. */
    suspend fun serve() = coroutineScope {
        launch { closeAfter(::discardInput) }
        closeAfter(::writeQueued)
    }

    /** Idempotent; a blocked write or read fails at once. */
    fun close() {
        outbox.close()
        socket.close()
    }

    private suspend fun writeQueued() {
        val output = socket.getOutputStream()
        for (document in outbox) {
            output.write(document)
            output.flush()
        }
    }

    private fun discardInput() {
        val input = socket.getInputStream()
        val buffer = ByteArray(DISCARD_BUFFER_SIZE)
        while (input.read(buffer) >= 0) continue
    }

    private suspend fun closeAfter(block: suspend () -> Unit) {
        try {
            block()
        } catch (_: IOException) {
            // The client hung up or was dropped; either way it is done.
        } finally {
            close()
        }
    }

    private companion object {
        const val DISCARD_BUFFER_SIZE = 1024
    }
}
