package org.ktcs.kernel.simulation

import kotlinx.coroutines.runBlocking
import org.koin.core.KoinApplication
import org.koin.core.module.Module
import org.koin.dsl.koinApplication
import org.ktcs.api.model.PlantModel
import org.ktcs.api.service.KernelServices
import org.ktcs.extension.config.KtcsConfig
import org.ktcs.kernel.context.KernelContext
import org.ktcs.kernel.context.RealTimeKernelContext
import org.ktcs.kernel.context.VirtualTimeKernelContext
import org.ktcs.kernel.core.KernelCore
import org.ktcs.kernel.kernelModule

/**
 * The whole kernel wired exactly as the application wires it, for simulations and tests: on virtual time by default
 * (the caller drives time with [context]'s `runUntil`), or on the wall clock with a [RealTimeKernelContext] given as
 * [clock] (then [onKernel] and [runUntil] wait for the kernel thread).
 */
class SimulationKernel(
    model: PlantModel,
    config: KtcsConfig,
    extensionModules: List<Module> = emptyList(),
    val clock: KernelContext = VirtualTimeKernelContext(),
) : AutoCloseable {
    // No eager instances: extensions that serve the network (XML channels) stay off in simulations.
    private val koin: KoinApplication = koinApplication(createEagerInstances = false) {
        modules(kernelModule(config, model, clock))
        modules(extensionModules)
    }
    val core: KernelCore = koin.koin.get()
    val services: KernelServices = koin.koin.get()

    /** The virtual clock; only for kernels on virtual time. */
    val context: VirtualTimeKernelContext
        get() = clock as? VirtualTimeKernelContext ?: error("this simulation kernel runs on the wall clock")

    init {
        onKernel { core.start() }
    }

    /** Runs [block] in the kernel context and returns its result. */
    fun <T> onKernel(block: () -> T): T = when (val clock = clock) {
        is VirtualTimeKernelContext -> {
            var result: Result<T>? = null
            clock.execute { result = runCatching(block) }
            clock.runUntil { result != null }
            result!!.getOrThrow()
        }

        else -> runBlocking { clock.call(block) }
    }

    /** Runs [action] in the kernel context and returns once it ran, then lets [settleMillis] of virtual time pass. */
    fun execute(settleMillis: Long = 0, action: KernelCore.() -> Unit) {
        onKernel { core.action() }
        if (settleMillis > 0) context.runUntilTime(context.elapsedMillis() + settleMillis)
    }

    /** Lets time pass (virtual: as fast as the kernel can; wall clock: in real time) until [stop] says so. */
    fun runUntil(stop: () -> Boolean) {
        when (val clock = clock) {
            is VirtualTimeKernelContext -> clock.runUntil(stop)
            else -> while (!onKernel(stop)) Thread.sleep(WALL_CLOCK_POLL_MILLIS)
        }
    }

    override fun close() {
        onKernel { core.stop() }
        clock.close()
        koin.close()
    }

    private companion object {
        const val WALL_CLOCK_POLL_MILLIS = 20L
    }
}
