package org.ktcs.kernel.store

import kotlinx.coroutines.runBlocking
import org.koin.dsl.bind
import org.koin.dsl.koinApplication
import org.koin.dsl.module
import org.ktcs.api.driver.VehicleDriverFactory
import org.ktcs.extension.config.KtcsConfig
import org.ktcs.kernel.app.PlantModelLoader
import org.ktcs.kernel.config.ConfigLoader
import org.ktcs.kernel.context.VirtualTimeKernelContext
import org.ktcs.kernel.core.KernelCore
import org.ktcs.kernel.core.StepDriverFactory
import org.ktcs.kernel.kernelModule
import java.nio.file.Path

/**
 * The demo plant's kernel on virtual time with a state store, started as `ktcs` starts it (restore, start, resume).
 * [crash] leaves it as a killed process would: what was committed stays, nothing is shut down in order.
 */
class RestartableKernel(val settings: List<String>) : AutoCloseable {
    val config: KtcsConfig = ConfigLoader().load(null, emptyMap(), settings)
    val context = VirtualTimeKernelContext()
    private val koin = koinApplication(createEagerInstances = false) {
        modules(
            kernelModule(config, PlantModelLoader.loadDemo().model, context),
            module { single { StepDriverFactory() } bind VehicleDriverFactory::class },
        )
    }
    val core: KernelCore = koin.koin.get()
    val durable: DurableState = checkNotNull(DurableState.open(config))
    val recovered: String = onKernel {
        durable.restoreInto(core)
        core.start()
        durable.resumeIn(core)
    }

    fun <T> onKernel(block: KernelCore.() -> T): T {
        var result: Result<T>? = null
        context.execute { result = runCatching { core.block() } }
        context.runUntil { result != null }
        return result!!.getOrThrow()
    }

    /** Lets virtual time pass until [done] or an hour passed. */
    fun runUntil(done: KernelCore.() -> Boolean) {
        val limit = context.elapsedMillis() + 3_600_000
        context.runUntil { core.done() || context.elapsedMillis() > limit }
    }

    /** Waits until everything changed so far is committed. */
    fun committed() {
        val mark = onKernel { commits.mark() }
        runBlocking { core.commits.awaitCommitted(mark) }
    }

    /** Commits what was changed, then drops the kernel without stopping it. */
    fun crash() {
        committed()
        durable.close()
        context.close()
        koin.close()
    }

    override fun close() {
        onKernel { stop() }
        durable.close()
        context.close()
        koin.close()
    }

    companion object {
        fun settingsFor(directory: Path, vararg more: String) =
            listOf("kernel.dataDirectory=$directory") + more
    }
}
