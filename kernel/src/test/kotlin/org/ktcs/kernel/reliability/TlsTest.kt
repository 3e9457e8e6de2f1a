package org.ktcs.kernel.reliability

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import io.kotest.matchers.string.shouldStartWith
import org.ktcs.kernel.app.KernelApplication
import org.ktcs.kernel.app.PlantModelLoader
import org.ktcs.kernel.config.ConfigLoader
import org.ktcs.kernel.web.WebTls
import java.net.URI
import java.net.http.HttpClient
import java.net.http.HttpRequest
import java.net.http.HttpResponse
import java.nio.file.Files
import java.nio.file.Path
import java.security.KeyStore
import java.util.Base64
import java.util.concurrent.TimeUnit
import javax.net.ssl.SSLContext
import javax.net.ssl.TrustManagerFactory
import kotlin.io.path.absolutePathString

/** HTTPS for the web API, the overview and the WebSocket (`web.tls.*`), checked with the JDK's TLS client. */
class TlsTest : FunSpec({
    val directory = Files.createTempDirectory(Path.of("target").toAbsolutePath(), "ktcs-tls")
    val keyStore = directory.resolve("ktcs.p12")
    // As the README tells operators to do it: a self-signed certificate for this machine, made with keytool.
    val keytool = Path.of(System.getProperty("java.home"), "bin", "keytool").toString()
    ProcessBuilder(
        keytool, "-genkeypair", "-alias", "ktcs", "-keyalg", "RSA", "-keysize", "2048", "-validity", "2",
        "-dname", "CN=localhost", "-ext", "SAN=dns:localhost,ip:127.0.0.1",
        "-keystore", keyStore.absolutePathString(), "-storetype", "PKCS12", "-storepass", "changeit",
    ).inheritIO().start().waitFor(60, TimeUnit.SECONDS) shouldBe true

    val store = KeyStore.getInstance("PKCS12").apply {
        Files.newInputStream(keyStore).use { load(it, "changeit".toCharArray()) }
    }
    val trusting = HttpClient.newBuilder().sslContext(trusting(store)).build()

    suspend fun withHttps(vararg settings: String, block: suspend (String) -> Unit) {
        val config = ConfigLoader().load(null, emptyMap(), listOf("web.bindAddress=127.0.0.1", "web.port=0") + settings)
        val application = KernelApplication(config, PlantModelLoader.loadDemo(), emptyList()) {}
        val ready = application.start()
        try {
            block(Regex("web API (https://\\S+/v1)").find(ready)!!.groupValues[1])
        } finally {
            application.stop()
        }
    }

    test("a key store serves the API and the WebSocket over HTTPS") {
        withHttps("web.tls.keyStore=$keyStore", "web.tls.keyStorePassword=changeit") { base ->
            val version = trusting.send(
                HttpRequest.newBuilder(URI("$base/kernel/version")).build(),
                HttpResponse.BodyHandlers.ofString(),
            )
            version.statusCode() shouldBe 200
            version.body() shouldContain "kTCS"
            version.sslSession().get().protocol shouldStartWith "TLSv1."

            val client = RecordingWebSocket()
            val socket = trusting.newWebSocketBuilder().buildAsync(
                URI(base.replace("https:", "wss:") + "/ws"),
                client,
            ).get()
            socket.sendText("""{"type":"subscribe","topics":["vehicles"]}""", true).get()
            client.messages.poll(10, TimeUnit.SECONDS)!! shouldContain "\"snapshot\""
            socket.abort()

            // A client that does not trust the certificate is refused; plain HTTP gets no answer from the TLS port.
            shouldThrow<javax.net.ssl.SSLHandshakeException> {
                HttpClient.newHttpClient().send(
                    HttpRequest.newBuilder(URI("$base/kernel/version")).build(),
                    HttpResponse.BodyHandlers.ofString(),
                )
            }
        }
    }

    test("a PEM certificate and key work the same way") {
        val certificate = directory.resolve("cert.pem")
        val key = directory.resolve("key.pem")
        Files.writeString(certificate, pem("CERTIFICATE", store.getCertificate("ktcs").encoded))
        Files.writeString(key, pem("PRIVATE KEY", store.getKey("ktcs", "changeit".toCharArray()).encoded))
        withHttps("web.tls.certificate=$certificate", "web.tls.privateKey=$key") { base ->
            trusting.send(HttpRequest.newBuilder(URI("$base/vehicles")).build(), HttpResponse.BodyHandlers.ofString())
                .statusCode() shouldBe 200
        }
    }

    test("a wrong password or a missing file is a one-line error naming the setting") {
        val config = ConfigLoader().load(
            null,
            emptyMap(),
            listOf("web.tls.keyStore=$keyStore", "web.tls.keyStorePassword=wrong"),
        )
        shouldThrow<WebTls.InvalidTlsSettings> { WebTls.from(config) }.message shouldContain "web.tls.keyStore"
        val missing = ConfigLoader().load(
            null,
            emptyMap(),
            listOf("web.tls.certificate=/nonexistent.pem", "web.tls.privateKey=/nonexistent.pem"),
        )
        shouldThrow<WebTls.InvalidTlsSettings> { WebTls.from(missing) }.message shouldContain "web.tls.certificate"
    }
})

private fun trusting(store: KeyStore): SSLContext {
    val trusted = KeyStore.getInstance("PKCS12").apply {
        load(null, null)
        setCertificateEntry("ktcs", store.getCertificate("ktcs"))
    }
    val factory = TrustManagerFactory.getInstance(TrustManagerFactory.getDefaultAlgorithm()).apply { init(trusted) }
    return SSLContext.getInstance("TLS").apply { init(null, factory.trustManagers, null) }
}

private fun pem(type: String, der: ByteArray): String =
    "-----BEGIN $type-----\n" + Base64.getMimeEncoder(64, "\n".toByteArray()).encodeToString(der) +
        "\n-----END $type-----\n"
