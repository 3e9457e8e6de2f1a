package org.ktcs.adapters.vda5050

import io.kotest.assertions.throwables.shouldThrowAny
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.nulls.shouldNotBeNull
import io.kotest.matchers.string.shouldContain
import org.ktcs.extension.config.ConfigException
import org.ktcs.kernel.app.KernelApplication
import java.net.InetAddress
import java.net.ServerSocket

/**
 * An embedded broker that cannot start stops kTCS at start-up with one line naming the setting and the problem (the
 * launcher prints a [ConfigException]'s message as it is), instead of a kTCS that never becomes ready.
 */
class Vda5050BrokerFailureTest : FunSpec({
    fun startFailure(vararg settings: String): ConfigException {
        val config = testConfig(*settings)
        val application = KernelApplication(config, vdaDemo(listOf("Point-0001")), listOf(Vda5050Extension()))
        val error = shouldThrowAny { application.start() }
        return generateSequence(error) { it.cause }.filterIsInstance<ConfigException>().firstOrNull().shouldNotBeNull()
    }

    test("a port in use names vda5050.embeddedBroker.port") {
        ServerSocket(0, 1, InetAddress.getLoopbackAddress()).use { taken ->
            startFailure("vda5050.embeddedBroker.port=${taken.localPort}").message!! shouldContain
                "vda5050.embeddedBroker.port ${taken.localPort} cannot be used: the embedded MQTT broker cannot " +
                "listen on 127.0.0.1:${taken.localPort}"
        }
    }

    test("an address that is not this machine's names vda5050.embeddedBroker.bindAddress") {
        // 192.0.2.1 is TEST-NET-1 (RFC 5737): no machine has it.
        startFailure("vda5050.embeddedBroker.bindAddress=192.0.2.1", "vda5050.embeddedBroker.port=${freePort()}")
            .message!! shouldContain "vda5050.embeddedBroker.bindAddress '192.0.2.1' cannot be used"
    }
})
