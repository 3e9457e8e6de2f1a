package org.ktcs.adapters.vda5050

import io.kotest.assertions.nondeterministic.eventually
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldContainExactly
import io.kotest.matchers.shouldBe
import org.ktcs.adapters.vda5050.mqtt.BrokerSettings
import java.util.Collections
import kotlin.time.Duration.Companion.seconds

/** Orders and instant actions leave on kTCS's sending thread, in the order the drivers handed them over. */
class Vda5050BrokerSendingTest : FunSpec({
    test("messages are sent on the sending thread in order; none after close, and a failing one stops no other") {
        val broker = Vda5050Broker(BrokerSettings(embeddedPort = freePort()))
        val sent = Collections.synchronizedList(mutableListOf<Pair<Int, String>>())
        (1..50).forEach { i ->
            broker.sending.execute {
                if (i == 10) throw IllegalStateException("the embedded MQTT broker is not running")
                sent += i to Thread.currentThread().name
            }
        }
        eventually(5.seconds) { sent.size shouldBe 49 }
        sent.map { it.first } shouldContainExactly (1..50).filter { it != 10 }
        sent.map { it.second }.toSet() shouldBe setOf(Vda5050Broker.SENDING_THREAD)
        broker.close()
        broker.sending.execute { sent += 0 to Thread.currentThread().name }
        Thread.sleep(100)
        sent.size shouldBe 49
    }
})
