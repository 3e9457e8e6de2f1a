package org.ktcs.kernel.bench

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import java.io.IOException
import java.net.ServerSocket
import kotlin.concurrent.thread

/** The bench's lean HTTP client: what it sends, and answers read off one keep-alive connection in turn. */
class RawHttpConnectionTest : FunSpec({
    /** A server that reads requests off one connection and writes [answers] in turn; returns what it read. */
    fun serve(server: ServerSocket, answers: List<String>, received: StringBuilder) = thread {
        server.accept().use { socket ->
            val input = socket.getInputStream().bufferedReader(Charsets.ISO_8859_1)
            answers.forEach { answer ->
                var length = 0
                while (true) {
                    val line = input.readLine() ?: return@thread
                    received.append(line).append('\n')
                    if (line.startsWith("Content-Length:")) length = line.substringAfter(':').trim().toInt()
                    if (line.isEmpty()) break
                }
                received.append(CharArray(length).also { input.read(it) }).append('\n')
                socket.getOutputStream().write(answer.toByteArray(Charsets.ISO_8859_1))
            }
        }
    }

    test("a POST encoded beforehand carries the path under the base URL, its length and its body") {
        val request = RawHttpConnection.postRequest("http://127.0.0.1:5/v1", "/transportOrders/A%20b", """{"ä":1}""")
        String(request, Charsets.UTF_8) shouldBe "POST /v1/transportOrders/A%20b HTTP/1.1\r\nHost: 127.0.0.1:5\r\n" +
            "Content-Type: application/json\r\nContent-Length: 8\r\n\r\n{\"ä\":1}"
    }

    test("answers with a length, chunked and with an error status are read in turn off one connection") {
        ServerSocket(0).use { server ->
            val received = StringBuilder()
            val answers = listOf(
                "HTTP/1.1 200 OK\r\nContent-Length: 5\r\nContent-Type: application/json\r\n\r\n{\"a\"}",
                "HTTP/1.1 200 OK\r\nTransfer-Encoding: chunked\r\n\r\n3\r\nabc\r\n2;x=y\r\nde\r\n0\r\n\r\n",
                "HTTP/1.1 409 Conflict\r\ncontent-length: 8\r\n\r\nconflict",
            )
            val serving = serve(server, answers, received)
            val base = "http://127.0.0.1:${server.localPort}/v1"
            RawHttpConnection(base).use { connection ->
                val bodies = listOf("1", "22", "333").map { body ->
                    connection.exchange(RawHttpConnection.postRequest(base, "/o", body))
                }
                bodies.map { it.status } shouldBe listOf(200, 200, 409)
                bodies.map { String(it.body) } shouldBe listOf("{\"a\"}", "abcde", "conflict")
            }
            serving.join()
            received.lines().filter { it.startsWith("POST") || (it.all(Char::isDigit) && it.isNotEmpty()) } shouldBe
                listOf("POST /v1/o HTTP/1.1", "1", "POST /v1/o HTTP/1.1", "22", "POST /v1/o HTTP/1.1", "333")
        }
    }

    test("a discarded answer counts its whole body, larger than the buffer, and the next answer follows it") {
        ServerSocket(0).use { server ->
            val large = "x".repeat(200_000)
            val answers = listOf(
                "HTTP/1.1 200 OK\r\nContent-Length: ${large.length}\r\n\r\n$large",
                "HTTP/1.1 200 OK\r\nTransfer-Encoding: chunked\r\n\r\n3\r\nabc\r\n0\r\n\r\n",
                "HTTP/1.1 200 OK\r\nContent-Length: 2\r\n\r\nok",
                "HTTP/1.1 404 Not Found\r\nContent-Length: 0\r\n\r\n",
            )
            val serving = serve(server, answers, StringBuilder())
            val base = "http://127.0.0.1:${server.localPort}/v1"
            RawHttpConnection(base).use { connection ->
                val get = RawHttpConnection.getRequest(base, "/transportOrders")
                connection.exchangeDiscarding(get) shouldBe 200_000L
                connection.exchangeDiscarding(get) shouldBe 3L
                String(connection.exchange(get).body) shouldBe "ok"
                shouldThrow<IllegalStateException> { connection.exchangeDiscarding(get) }.message shouldBe
                    "kTCS answered 404"
            }
            serving.join()
        }
    }

    test("an HTTPS kTCS is refused with the client that can talk to it") {
        shouldThrow<IllegalArgumentException> { RawHttpConnection("https://127.0.0.1:1/v1") }.message shouldBe
            "the raw client speaks plain HTTP, not https: use --client jdk"
    }

    test("a connection closed in the middle of an answer is an error, not a short body") {
        ServerSocket(0).use { server ->
            val serving = serve(server, listOf("HTTP/1.1 200 OK\r\nContent-Length: 50\r\n\r\nshort"), StringBuilder())
            val base = "http://127.0.0.1:${server.localPort}/v1"
            RawHttpConnection(base).use { connection ->
                shouldThrow<IOException> { connection.exchange(RawHttpConnection.postRequest(base, "/o", "{}")) }
            }
            serving.join()
        }
    }
})
