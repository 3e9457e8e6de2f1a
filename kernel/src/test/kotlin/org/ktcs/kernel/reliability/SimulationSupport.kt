package org.ktcs.kernel.reliability

import org.koin.dsl.bind
import org.koin.dsl.module
import org.ktcs.api.driver.VehicleDriverFactory
import org.ktcs.api.model.PlantModel
import org.ktcs.kernel.app.PlantModelLoader
import org.ktcs.kernel.config.ConfigLoader
import org.ktcs.kernel.core.KernelCore
import org.ktcs.kernel.core.StepDriverFactory
import org.ktcs.kernel.simulation.SimulationKernel

/** The demo plant on virtual time with test vehicles, as the reliability tests drive it. */
fun demoKernel(vararg settings: String, change: (PlantModel) -> PlantModel = { it }): SimulationKernel {
    val config = ConfigLoader().load(null, emptyMap(), listOf(*settings))
    val drivers = module { single { StepDriverFactory() } bind VehicleDriverFactory::class }
    return SimulationKernel(change(PlantModelLoader.loadDemo().model), config, listOf(drivers))
}

/** Runs [action] in the kernel context and returns its result (or throws its exception). */
fun <T> SimulationKernel.inKernel(action: KernelCore.() -> T): T {
    var result: Result<T>? = null
    context.execute { result = runCatching { core.action() } }
    context.runUntil { result != null }
    return result!!.getOrThrow()
}

/** Resources held by more than one vehicle, each with its holders; empty when the invariant holds. */
fun SimulationKernel.doublyHeld(): Map<String, List<String>> = core.scheduler.allocations()
    .flatMap { (vehicle, resources) -> resources.map { it to vehicle } }
    .groupBy({ it.first }, { it.second })
    .filterValues { it.size > 1 }

/** Points two vehicles report as their position at once; empty when the invariant holds. */
fun SimulationKernel.sharedPositions(): Map<String, List<String>> = core.plant.vehicles()
    .filter { it.currentPosition != null }
    .groupBy({ it.currentPosition!! }, { it.name })
    .filterValues { it.size > 1 }
