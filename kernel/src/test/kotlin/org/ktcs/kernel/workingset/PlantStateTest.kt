package org.ktcs.kernel.workingset

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.nulls.shouldBeNull
import io.kotest.matchers.shouldBe
import org.ktcs.kernel.app.PlantModelLoader
import org.ktcs.kernel.events.EventBus
import java.util.concurrent.atomic.AtomicBoolean
import java.util.concurrent.atomic.AtomicReference
import kotlin.concurrent.thread

class PlantStateTest : FunSpec({
    val demo = PlantModelLoader.loadDemo().model

    test("the layout with locks shows a lock at once, with vehicles as loaded") {
        val plant = PlantState(demo, EventBus())
        val path = demo.paths.first().name
        plant.updateVehicle("Vehicle-01") { it.copy(energyLevel = 7) }

        plant.setPathLocked(path, true)

        plant.layoutWithLocks().paths.first { it.name == path }.locked shouldBe true
        plant.layoutWithLocks().vehicles shouldBe demo.vehicles
        plant.publishedVehicle("Vehicle-01")!!.energyLevel shouldBe 7
    }

    // Drivers read from their own threads while the kernel changes the plant: they must never see a half-done change.
    test("a driver thread reads vehicles and the layout consistently while the kernel replaces the plant") {
        val plant = PlantState(demo, EventBus())
        val failure = AtomicReference<Throwable?>(null)
        val running = AtomicBoolean(true)
        val driver = thread {
            try {
                while (running.get()) {
                    checkNotNull(plant.publishedVehicle("Vehicle-01")) { "Vehicle-01 went missing" }
                    plant.publishedVehicles().mapNotNull { it.currentPosition }
                    plant.layoutWithLocks().paths.size
                }
            } catch (error: Throwable) {
                failure.set(error)
            }
        }
        val until = System.nanoTime() + 300_000_000L
        var locked = false
        while (System.nanoTime() < until && failure.get() == null) {
            plant.replace(demo)
            locked = !locked
            plant.setPathLocked(demo.paths.first().name, locked)
        }
        running.set(false)
        driver.join()

        failure.get().shouldBeNull()
    }
})
