package org.ktcs.xmlchannels.status

import io.ktor.utils.io.readAvailable
import io.ktor.utils.io.writeFully
import kotlinx.coroutines.Job
import kotlinx.coroutines.cancel
import kotlinx.coroutines.cancelChildren
import kotlinx.coroutines.channels.Channel
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.job
import kotlinx.coroutines.launch
import org.ktcs.xmlchannels.Connection
import java.io.IOException

/**
 * One status channel client: a bounded queue of documents and the connection they are written to. Whatever the
 * client sends is read and thrown away, which also notices when it hangs up.
 */
internal class StatusClient(private val connection: Connection, capacity: Int) {
    private val outbox = Channel<ByteArray>(capacity)

    val address: String get() = connection.address

    /** Queues [document]; `false` only if the queue is full, i.e. the client does not keep up. */
    fun offer(document: ByteArray): Boolean = outbox.trySend(document).let { it.isSuccess || it.isClosed }

    @Volatile
    private var serving: Job? = null

    /**
     * Writes queued documents until the client hangs up or is dropped. The connection itself is closed by whoever
     * accepted it, once this returns: closing it while a write is pending would race with that write.
     */
    suspend fun serve() = coroutineScope {
        serving = coroutineContext.job
        launch {
            ignoringIOFailure(::discardInput)
            this@coroutineScope.cancel("the client hung up")
        }
        ignoringIOFailure(::writeQueued)
        coroutineContext.cancelChildren()
    }

    /** Drops the client: ends a pending write at once; idempotent. */
    fun close() {
        outbox.close()
        serving?.cancel()
    }

    private suspend fun writeQueued() {
        for (document in outbox) {
            connection.output.writeFully(document)
            connection.output.flush()
        }
    }

    private suspend fun discardInput() {
        val buffer = ByteArray(DISCARD_BUFFER_SIZE)
        while (connection.input.readAvailable(buffer, 0, buffer.size) >= 0) continue
    }

    private suspend fun ignoringIOFailure(block: suspend () -> Unit) {
        try {
            block()
        } catch (_: IOException) {
            // The client hung up or the connection failed; either way it is done.
        }
    }

    private companion object {
        const val DISCARD_BUFFER_SIZE = 1024
    }
}
