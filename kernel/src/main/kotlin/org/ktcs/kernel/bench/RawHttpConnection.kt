package org.ktcs.kernel.bench

import java.io.BufferedInputStream
import java.io.ByteArrayOutputStream
import java.io.IOException
import java.io.InputStream
import java.io.OutputStream
import java.net.InetSocketAddress
import java.net.Socket
import java.net.URI

/**
 * One HTTP/1.1 keep-alive connection that sends requests encoded beforehand and reads each answer's status and body
 * with as little work as HTTP allows: the bench's lean client (`--client raw`). On a machine whose cores the client
 * shares with kTCS, the JDK's `HttpClient` costs about as much CPU per request as kTCS spends answering it, so the
 * creation rate it measures is partly the client's; this one measures kTCS.
 */
class RawHttpConnection(baseUrl: String) : AutoCloseable {
    private val uri = URI.create(baseUrl).also {
        require(it.scheme == "http") { "the raw client speaks plain HTTP, not ${it.scheme}: use --client jdk" }
    }
    private val socket = Socket().apply {
        tcpNoDelay = true
        connect(InetSocketAddress(uri.host, uri.port), CONNECT_TIMEOUT_MILLIS)
        soTimeout = READ_TIMEOUT_MILLIS
    }
    private val input: InputStream = BufferedInputStream(socket.getInputStream(), BUFFER_BYTES)
    private val output: OutputStream = socket.getOutputStream()
    private val line = StringBuilder()
    private val discardBuffer by lazy { ByteArray(DISCARD_BUFFER_BYTES) }

    /** Sends [request] (from [postRequest] or [getRequest]) and reads the answer; returns its status code and body. */
    fun exchange(request: ByteArray): Answer {
        val head = send(request)
        val body = when {
            head.chunked -> readChunked()
            else -> readExactly(head.length)
        }
        return Answer(head.status, body)
    }

    /**
     * Sends [request] and reads the answer's body into one reused buffer, as a client that parses while it reads
     * would; returns the body's length in bytes. Fails on any status but 200.
     */
    fun exchangeDiscarding(request: ByteArray): Long {
        val head = send(request)
        check(head.status == HTTP_OK) { "kTCS answered ${head.status}" }
        if (head.chunked) return readChunked().size.toLong()
        var left = head.length
        while (left > 0) {
            val n = input.read(discardBuffer, 0, minOf(left, discardBuffer.size))
            if (n < 0) throw IOException("kTCS closed the connection in the middle of an answer")
            left -= n
        }
        return head.length.toLong()
    }

    private fun send(request: ByteArray): Head {
        output.write(request)
        output.flush()
        val status = readLine().split(' ', limit = STATUS_PARTS).getOrNull(1)?.toIntOrNull()
            ?: throw IOException("kTCS answered without an HTTP status line")
        var length = -1
        var chunked = false
        while (true) {
            val header = readLine()
            if (header.isEmpty()) break
            val name = header.substringBefore(':').trim()
            val value = header.substringAfter(':').trim()
            if (name.equals("Content-Length", ignoreCase = true)) length = value.toInt()
            if (name.equals("Transfer-Encoding", ignoreCase = true) && value.contains("chunked", true)) chunked = true
        }
        if (!chunked && length < 0) throw IOException("kTCS answered without Content-Length on a keep-alive connection")
        return Head(status, length, chunked)
    }

    private class Head(val status: Int, val length: Int, val chunked: Boolean)

    override fun close() = socket.close()

    private fun readChunked(): ByteArray {
        val body = ByteArrayOutputStream()
        while (true) {
            val size = readLine().substringBefore(';').trim().toInt(HEX)
            if (size == 0) {
                while (readLine().isNotEmpty()) Unit // trailers
                return body.toByteArray()
            }
            body.write(readExactly(size))
            readLine()
        }
    }

    private fun readExactly(count: Int): ByteArray {
        val bytes = ByteArray(count)
        var read = 0
        while (read < count) {
            val n = input.read(bytes, read, count - read)
            if (n < 0) throw IOException("kTCS closed the connection in the middle of an answer")
            read += n
        }
        return bytes
    }

    private fun readLine(): String {
        line.setLength(0)
        while (true) {
            val byte = input.read()
            if (byte < 0) throw IOException("kTCS closed the connection")
            if (byte == '\n'.code) break
            if (byte != '\r'.code) line.append(byte.toChar())
        }
        return line.toString()
    }

    /** An answer's status code and body bytes. */
    class Answer(val status: Int, val body: ByteArray)

    companion object {
        private const val CONNECT_TIMEOUT_MILLIS = 5000
        private const val READ_TIMEOUT_MILLIS = 30_000
        private const val BUFFER_BYTES = 16 * 1024
        private const val STATUS_PARTS = 3
        private const val HEX = 16
        private const val HTTP_OK = 200
        private const val DISCARD_BUFFER_BYTES = 64 * 1024

        /** The bytes of a `GET` of [path] under [baseUrl]'s path, for a keep-alive connection. */
        fun getRequest(baseUrl: String, path: String): ByteArray {
            val uri = URI.create(baseUrl)
            return "GET ${uri.rawPath}$path HTTP/1.1\r\nHost: ${uri.host}:${uri.port}\r\n\r\n".toByteArray(
                Charsets.US_ASCII,
            )
        }

        /** The bytes of a `POST` of [body] (JSON) to [path] under [baseUrl]'s path, for a keep-alive connection. */
        fun postRequest(baseUrl: String, path: String, body: String): ByteArray {
            val uri = URI.create(baseUrl)
            val content = body.toByteArray(Charsets.UTF_8)
            val head = "POST ${uri.rawPath}$path HTTP/1.1\r\n" +
                "Host: ${uri.host}:${uri.port}\r\n" +
                "Content-Type: application/json\r\n" +
                "Content-Length: ${content.size}\r\n\r\n"
            return head.toByteArray(Charsets.US_ASCII) + content
        }
    }
}
