package org.ktcs.examples.clients

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.nulls.shouldNotBeNull
import io.kotest.matchers.shouldBe
import kotlinx.coroutines.withTimeout
import org.ktcs.adapters.loopback.LoopbackExtension
import org.ktcs.api.order.TransportOrderState
import org.ktcs.kernel.app.KernelApplication
import org.ktcs.kernel.app.PlantModelLoader
import org.ktcs.kernel.config.ConfigLoader
import org.ktcs.kernel.services.StandardKernelServices
import kotlin.time.Duration.Companion.seconds

/** The kernel services in-process: an order created through them is followed to FINISHED on their event flow. */
class InProcessOrdersTest : FunSpec({
    val config = ConfigLoader().load(
        null,
        emptyMap(),
        listOf("web.bindAddress=127.0.0.1", "web.port=0", "loopback.timeFactor=20"),
    )
    val application = KernelApplication(config, PlantModelLoader.loadDemo(), listOf(LoopbackExtension()))
    application.start()
    afterSpec { application.stop() }

    test("an order created with the kernel services is returned once it finished") {
        val services = StandardKernelServices(application.kernel)
        val order = withTimeout(60.seconds) { InProcessOrders(services).deliver("In-1", "Storage 01", "Goods out 01") }
        order.state shouldBe TransportOrderState.FINISHED
        order.processingVehicle.shouldNotBeNull()
        services.transportOrders.transportOrder("In-1")?.state shouldBe TransportOrderState.FINISHED
    }
})
