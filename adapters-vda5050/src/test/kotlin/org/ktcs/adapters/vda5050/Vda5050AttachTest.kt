package org.ktcs.adapters.vda5050

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldContain
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import org.ktcs.adapters.loopback.LoopbackExtension
import org.ktcs.kernel.app.KernelApplication
import org.ktcs.kernel.app.PlantModelLoader

/**
 * Which vehicles get the VDA 5050 driver: kTCS's or openTCS's name in `tcs:preferredAdapterClass`, or
 * `vda5050:version` without a preferred driver, even with the loopback driver available; a vehicle with a missing
 * property gets no driver, and the log and a notification say which property.
 */
class Vda5050AttachTest : FunSpec({
    test("attach rules, and a vehicle with a missing property is not attached") {
        val demo = PlantModelLoader.loadDemo()
        val (v1, v2, v3, v4) = demo.model.vehicles
        val vehicles = listOf(
            v1.copy(properties = vdaProperties("S1")),
            v2.copy(
                properties = vdaProperties(
                    "S2",
                ) + ("tcs:preferredAdapterClass" to Vda5050DriverFactory.OPENTCS_FACTORY),
            ),
            v3.copy(
                properties = vdaProperties("S3") - "vda5050:serialNumber" + ("tcs:preferredAdapterClass" to "vda5050"),
            ),
            v4,
        )
        val port = freePort()
        val config = testConfig(
            "vda5050.embeddedBroker.port=$port",
            // Attaching is what is tested: enabled drivers would start the broker, for nothing here.
            "kernel.enableDriversOnStart=false",
        )
        val application = KernelApplication(
            config,
            demo.copy(model = demo.model.copy(vehicles = vehicles)),
            listOf(LoopbackExtension(), Vda5050Extension()),
        )
        val log = logLinesOf("org.ktcs.kernel.vehicles.VehicleControllers")
        application.start()
        try {
            val kernel = application.kernel
            val drivers = kernel.plant.vehicles().associate { it.name to kernel.controllers.driverName(it.name) }
            drivers shouldBe mapOf(
                v1.name to "vda5050",
                v2.name to "vda5050",
                v3.name to null,
                v4.name to "loopback",
            )
            log.single { v3.name in it } shouldContain "property vda5050:serialNumber is missing"
            application.kernel.notifications.recent().map { it.text } shouldContain
                "vehicle ${v3.name} has no driver: driver 'vda5050' cannot drive vehicle '${v3.name}': " +
                "vehicle ${v3.name}: property vda5050:serialNumber is missing"
        } finally {
            application.stop()
        }
    }
})
