package org.ktcs.kernel.app

import kotlinx.coroutines.runBlocking
import org.koin.core.KoinApplication
import org.koin.core.logger.Level
import org.koin.dsl.koinApplication
import org.koin.dsl.module
import org.koin.logger.slf4jLogger
import org.ktcs.kernel.config.KtcsConfig
import org.ktcs.kernel.context.RealTimeKernelContext
import org.ktcs.kernel.core.KernelCore
import org.ktcs.kernel.extension.ExtensionException
import org.ktcs.kernel.extension.KtcsExtension
import org.ktcs.kernel.extension.ServedAddresses
import org.ktcs.kernel.kernelModule
import org.ktcs.kernel.web.KernelVersion
import org.ktcs.kernel.web.ShutdownRequest
import org.ktcs.kernel.web.WebServer
import org.slf4j.LoggerFactory

/**
 * The kernel application: wires the kernel and its extensions with Koin and serves them. One instance per process;
 * tests start it in-process on free ports.
 */
class KernelApplication(
    private val config: KtcsConfig,
    private val loaded: LoadedModel,
    private val extensions: List<KtcsExtension>,
    private val shutdownRequest: ShutdownRequest = ShutdownRequest {},
) {
    private val log = LoggerFactory.getLogger(KernelApplication::class.java)
    private var koin: KoinApplication? = null
    private val context = RealTimeKernelContext()

    /** The kernel, once started. */
    val kernel: KernelCore get() = checkNotNull(koin) { "kTCS is not started" }.koin.get()

    /** Starts everything and returns the line announcing readiness (also logged). */
    fun start(): String {
        // Extensions that start at once (the XML channels) are created after the kernel started, so their first
        // request finds it running.
        val app = koinApplication(createEagerInstances = false) {
            slf4jLogger(Level.ERROR)
            modules(kernelModule(config, loaded.model, context), applicationModule())
            extensions.forEach { extension -> modules(moduleOf(extension)) }
        }
        koin = app
        val core = app.koin.get<KernelCore>()
        runBlocking { context.call { core.start() } }
        app.createEagerInstances()
        val webAddress = app.koin.get<WebServer>().start()
        val ready =
            readyLine(listOf("web API $webAddress/v1") + app.koin.getAll<ServedAddresses>().flatMap { it.addresses() })
        log.info(ready)
        return ready
    }

    fun stop() {
        koin?.let { app ->
            app.koin.get<WebServer>().stop()
            val core = app.koin.get<KernelCore>()
            runBlocking { context.call { core.stop() } }
            context.close()
            app.close()
        }
        koin = null
        log.info("kTCS stopped")
    }

    private fun applicationModule() = module {
        single { KernelVersion.ofThisBuild() }
        single { WebServer(get(), get(), get(), shutdownRequest, getAll()) }
    }

    private fun moduleOf(extension: KtcsExtension) = try {
        extension.module()
    } catch (error: RuntimeException) {
        throw ExtensionException("extension '${extension.name}' failed to provide its module: ${error.message}", error)
    }

    private fun readyLine(addresses: List<String>): String {
        val model = loaded.model
        val extensionNames = extensions.joinToString { it.name }.ifEmpty { "none" }
        return "kTCS ready: model '${model.name}' from ${loaded.source} (${model.summary()}); " +
            "${addresses.joinToString("; ")}; extensions: $extensionNames"
    }
}
