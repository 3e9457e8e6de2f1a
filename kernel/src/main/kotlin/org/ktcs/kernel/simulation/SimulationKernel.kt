package org.ktcs.kernel.simulation

import org.koin.core.KoinApplication
import org.koin.core.module.Module
import org.koin.dsl.koinApplication
import org.ktcs.api.model.PlantModel
import org.ktcs.api.service.KernelServices
import org.ktcs.kernel.config.KtcsConfig
import org.ktcs.kernel.context.VirtualTimeKernelContext
import org.ktcs.kernel.core.KernelCore
import org.ktcs.kernel.kernelModule

/**
 * The whole kernel on virtual time, wired exactly as the application wires it, for simulations and tests: the
 * caller drives time with [context]'s `runUntil`.
 */
class SimulationKernel(
    model: PlantModel,
    config: KtcsConfig,
    extensionModules: List<Module> = emptyList(),
    val context: VirtualTimeKernelContext = VirtualTimeKernelContext(),
) : AutoCloseable {
    // No eager instances: extensions that serve the network (XML channels) stay off in simulations.
    private val koin: KoinApplication = koinApplication(createEagerInstances = false) {
        modules(kernelModule(config, model, context))
        modules(extensionModules)
    }
    val core: KernelCore = koin.koin.get()
    val services: KernelServices = koin.koin.get()

    init {
        var started = false
        context.execute {
            core.start()
            started = true
        }
        context.runUntil { started }
    }

    override fun close() {
        var stopped = false
        context.execute {
            core.stop()
            stopped = true
        }
        context.runUntil { stopped }
        context.close()
        koin.close()
    }
}
