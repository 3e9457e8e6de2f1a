package org.ktcs.xmlchannels

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.FunSpec
import io.kotest.engine.spec.tempdir
import io.kotest.matchers.collections.shouldContain
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldEndWith
import org.koin.dsl.koinApplication
import org.koin.dsl.module
import org.ktcs.api.service.KernelServices
import org.ktcs.extension.KtcsExtension
import org.ktcs.kernel.config.ConfigLoader
import org.ktcs.xmlchannels.status.StatusClientSocket
import java.net.BindException
import java.net.ConnectException
import java.net.ServerSocket
import java.nio.file.Files
import java.util.ServiceLoader

class XmlChannelsExtensionTest : FunSpec({
    test("the kernel finds the extension through the service loader") {
        ServiceLoader.load(KtcsExtension::class.java).map { it.name } shouldContain "xml-channels"
    }

    test("the ports come from kTCS's configuration") {
        val config = ConfigLoader().load(null, emptyMap(), listOf("xml.orders.port=6000", "xml.status.port=6001"))

        XmlChannelSettings.from(config).let { it.ordersPort to it.statusPort } shouldBe (6000 to 6001)
    }

    test("the channels listen as soon as the kernel's Koin application exists, and stop when it closes") {
        val services = FakeKernelServices()
        val scripts = tempdir("ktcs-scripts").toPath()
        val app = koinApplication {
            modules(module { single<KernelServices> { services } }, xmlChannelsModule { testSettings(scripts) })
        }
        // Nothing asked for the channels yet: they were started at start, which writes the scripts' template.
        Files.list(scripts).use { it.count() } shouldBe 1L
        val channels = app.koin.get<XmlChannels>()
        val statusClient = StatusClientSocket(channels.statusPort)
        HostClient.send(channels.ordersPort, "<tcsOrderSet/>") shouldEndWith "<tcsResponseSet/>"

        app.close()

        statusClient.next() shouldBe null
        shouldThrow<ConnectException> { HostClient.connect(channels.ordersPort) }
        shouldThrow<ConnectException> { HostClient.connect(channels.statusPort) }
    }

    test("a port that is taken fails the start") {
        ServerSocket(0).use { taken ->
            val settings = testSettings().copy(statusPort = taken.localPort)
            shouldThrow<BindException> { XmlChannels(FakeKernelServices(), settings).start() }
        }
    }
})
