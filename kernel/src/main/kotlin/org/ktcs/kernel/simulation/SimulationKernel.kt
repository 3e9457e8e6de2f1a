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
        execute { start() }
    }

    /** Runs [action] in the kernel context and returns once it ran, then lets [settleMillis] of virtual time pass. */
    fun execute(settleMillis: Long = 0, action: KernelCore.() -> Unit) {
        var done = false
        context.execute {
            core.action()
            done = true
        }
        context.runUntil { done }
        if (settleMillis > 0) context.runUntilTime(context.elapsedMillis() + settleMillis)
    }

    override fun close() {
        execute { stop() }
        context.close()
        koin.close()
    }
}
