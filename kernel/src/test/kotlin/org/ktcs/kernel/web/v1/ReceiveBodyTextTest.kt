package org.ktcs.kernel.web.v1

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import io.ktor.client.request.post
import io.ktor.client.request.setBody
import io.ktor.client.statement.bodyAsText
import io.ktor.http.ContentType
import io.ktor.http.HttpStatusCode
import io.ktor.http.content.OutgoingContent
import io.ktor.http.withCharset
import io.ktor.server.application.createApplicationPlugin
import io.ktor.server.application.hooks.ReceiveRequestBytes
import io.ktor.server.application.install
import io.ktor.server.response.respondText
import io.ktor.server.routing.post
import io.ktor.server.routing.routing
import io.ktor.server.testing.testApplication
import io.ktor.utils.io.ByteWriteChannel
import io.ktor.utils.io.writeFully
import org.ktcs.kernel.web.plugins.RequestSizeLimit
import org.ktcs.kernel.web.plugins.installErrorResponses
import java.util.concurrent.atomic.AtomicInteger

class ReceiveBodyTextTest : FunSpec({
    /** A POST /echo that answers the body as [receiveBodyText] read it; [piped] counts bodies read through Ktor's pipeline. */
    fun echo(piped: AtomicInteger, test: suspend io.ktor.server.testing.ApplicationTestBuilder.() -> Unit) =
        testApplication {
            application {
                installErrorResponses()
                install(RequestSizeLimit) { maxBytes = 64 }
                install(
                    createApplicationPlugin("CountPiped") {
                        on(ReceiveRequestBytes) { _, body -> body.also { piped.incrementAndGet() } }
                    },
                )
                routing { post("/echo") { call.respondText(call.receiveBodyText()) } }
            }
            test()
        }

    test("a body with a Content-Length is read from the connection, in the charset its Content-Type names") {
        val piped = AtomicInteger()
        echo(piped) {
            client.post("/echo") {
                setBody(LengthContent("{\"a\":\"Grüße\"}".toByteArray(Charsets.UTF_8), ContentType.Application.Json))
            }.bodyAsText() shouldBe "{\"a\":\"Grüße\"}"
            val latin1 = ContentType.Application.Json.withCharset(Charsets.ISO_8859_1)
            client.post("/echo") {
                setBody(LengthContent("{\"a\":\"Grüße\"}".toByteArray(Charsets.ISO_8859_1), latin1))
            }.bodyAsText() shouldBe "{\"a\":\"Grüße\"}"
        }
        piped.get() shouldBe 0
    }

    test("a body without a Content-Length goes through the pipeline, which refuses it past the size limit") {
        val piped = AtomicInteger()
        echo(piped) {
            client.post("/echo") { setBody(ChunkedContent(ByteArray(10) { 'x'.code.toByte() })) }.let {
                it.status shouldBe HttpStatusCode.OK
                it.bodyAsText() shouldBe "x".repeat(10)
            }
            client.post("/echo") { setBody(ChunkedContent(ByteArray(100) { 'x'.code.toByte() })) }.status shouldBe
                HttpStatusCode.PayloadTooLarge
        }
        piped.get() shouldBe 2
    }
})

private class LengthContent(private val bytes: ByteArray, override val contentType: ContentType) :
    OutgoingContent.ByteArrayContent() {
    override val contentLength: Long = bytes.size.toLong()

    override fun bytes(): ByteArray = bytes
}

private class ChunkedContent(private val bytes: ByteArray) : OutgoingContent.WriteChannelContent() {
    override val contentType: ContentType = ContentType.Application.Json

    override suspend fun writeTo(channel: ByteWriteChannel) = channel.writeFully(bytes)
}
