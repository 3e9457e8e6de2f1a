package org.ktcs.kernel.core

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldStartWith
import org.koin.dsl.module
import org.ktcs.api.scheduling.Scheduler
import org.ktcs.kernel.app.PlantModelLoader
import org.ktcs.kernel.config.ConfigLoader
import org.ktcs.kernel.context.KernelContext
import org.ktcs.kernel.scheduling.DefaultScheduler
import org.ktcs.kernel.simulation.SimulationKernel

/**
 * A scheduler an extension puts in place of the default one: it keeps the kernel's one in it (as a wrapper would) but
 * is no [DefaultScheduler], and reports the waits it knows of through the `api` interface only.
 */
private class ReplacementScheduler(inner: Scheduler) : Scheduler by inner {
    var waits: Map<String, Map<String, Set<String>>> = emptyMap()

    override fun waitsFor() = waits
}

/** The deadlock watchdog works with whatever scheduler is in place: it asks the `api` interface, nothing else. */
class ReplacedSchedulerTest : FunSpec({
    val config = ConfigLoader().load(null, emptyMap(), listOf("kernel.deadlockCheckInterval=0"))
    val demo = PlantModelLoader.loadDemo().model
    val replacing = module {
        single<Scheduler> { ReplacementScheduler(DefaultScheduler(get(), get<KernelContext>())) }
    }

    test("a deadlock only the replacement knows of is reported") {
        SimulationKernel(demo, config, listOf(replacing)).use { kernel ->
            val scheduler = kernel.core.scheduler as ReplacementScheduler
            kernel.execute { checkForDeadlocks() }
            kernel.core.watchdog.detected shouldBe 0

            scheduler.waits = mapOf(
                "Vehicle-01" to mapOf("Vehicle-02" to setOf("Point-0002")),
                "Vehicle-02" to mapOf("Vehicle-01" to setOf("Point-0001")),
            )
            kernel.execute { checkForDeadlocks() }

            kernel.core.watchdog.detected shouldBe 1
            kernel.core.notifications.recent().map {
                it.text
            }.filter { it.startsWith("deadlock") }.single() shouldStartWith
                "deadlock: vehicles Vehicle-01 -> Vehicle-02 wait for each other; contested resources Point-0001, Point-0002"
        }
    }
})
