package org.ktcs.adapters.vda5050

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import org.ktcs.extension.config.ConfigException
import org.ktcs.kernel.config.ConfigLoader

/** The embedded broker's pause between rounds of work: 0 to 50 ms, 5 by default, a bad value named. */
class Vda5050SettingsTest : FunSpec({
    val loader = ConfigLoader()

    test("the pause is 5 ms unless set, and 0 turns it off") {
        Vda5050Extension.settingsFrom(loader.load(null, emptyMap(), emptyList())).embeddedBatchMillis shouldBe 5
        val off = loader.load(null, emptyMap(), listOf("vda5050.embeddedBroker.batchMillis=0"))
        Vda5050Extension.settingsFrom(off).embeddedBatchMillis shouldBe 0
    }

    test("a pause out of range or not a number is refused with the setting named") {
        shouldThrow<ConfigException> {
            loader.load(null, emptyMap(), listOf("vda5050.embeddedBroker.batchMillis=51"))
        }.message shouldBe "--set vda5050.embeddedBroker.batchMillis: bad value '51' for " +
            "vda5050.embeddedBroker.batchMillis: must be between 0 and 50"
        shouldThrow<ConfigException> {
            loader.load(null, mapOf("KTCS_VDA5050_EMBEDDEDBROKER_BATCHMILLIS" to "soon"), emptyList())
        }.message shouldBe "environment variable KTCS_VDA5050_EMBEDDEDBROKER_BATCHMILLIS: bad value 'soon' for " +
            "vda5050.embeddedBroker.batchMillis: expected a whole number"
    }
})
