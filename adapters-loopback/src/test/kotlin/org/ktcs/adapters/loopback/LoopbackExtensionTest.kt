package org.ktcs.adapters.loopback

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldHaveSingleElement
import io.kotest.matchers.shouldBe
import io.kotest.matchers.types.shouldBeInstanceOf
import org.koin.dsl.koinApplication
import org.ktcs.api.driver.VehicleDriverFactory
import org.ktcs.kernel.config.ConfigLoader
import org.ktcs.kernel.extension.Extensions

class LoopbackExtensionTest : FunSpec({
    test("is found on the class path through ServiceLoader") {
        Extensions.discover().filterIsInstance<LoopbackExtension>() shouldHaveSingleElement { it.name == "loopback" }
    }

    test("contributes a loopback driver factory as a VehicleDriverFactory") {
        val koin = koinApplication { modules(LoopbackExtension().module()) }.koin
        val factory = koin.getAll<VehicleDriverFactory>().single()
        factory.shouldBeInstanceOf<LoopbackDriverFactory>()
        factory.name shouldBe "loopback"
    }

    test("takes its settings from the loopback.* configuration keys") {
        val config = ConfigLoader().load(
            null,
            emptyMap(),
            listOf("loopback.timeFactor=4", "loopback.energyDrainPercentPerKm=2.5"),
        )
        val settings = LoopbackExtension.settingsFrom(config)
        settings.timeFactor shouldBe 4.0
        settings.energyDrainPercentPerKm shouldBe 2.5
        settings.operatingTimeMillis shouldBe 5000
    }
})
