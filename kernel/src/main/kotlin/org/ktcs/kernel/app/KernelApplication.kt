package org.ktcs.kernel.app

import kotlinx.coroutines.runBlocking
import org.koin.core.KoinApplication
import org.koin.core.logger.Level
import org.koin.dsl.koinApplication
import org.koin.dsl.module
import org.koin.logger.slf4jLogger
import org.ktcs.extension.ExtensionException
import org.ktcs.extension.KtcsExtension
import org.ktcs.extension.ServedAddresses
import org.ktcs.extension.config.KtcsConfig
import org.ktcs.extension.web.WebServerInfo
import org.ktcs.kernel.config.KtcsSettings
import org.ktcs.kernel.context.RealTimeKernelContext
import org.ktcs.kernel.core.KernelCore
import org.ktcs.kernel.extension.ExtensionFailures
import org.ktcs.kernel.extension.describe
import org.ktcs.kernel.extension.from
import org.ktcs.kernel.kernelModule
import org.ktcs.kernel.store.DurableState
import org.ktcs.kernel.web.KernelEventTap
import org.ktcs.kernel.web.KernelVersion
import org.ktcs.kernel.web.ShutdownRequest
import org.ktcs.kernel.web.WebServer
import org.slf4j.LoggerFactory
import java.nio.file.Path

/**
 * The kernel application: wires the kernel and its extensions with Koin and serves them. One instance per process;
 * tests start it in-process on free ports.
 */
class KernelApplication(
    private val config: KtcsConfig,
    private val loaded: LoadedModel,
    private val extensions: List<KtcsExtension>,
    /** The jar an extension came from (for the ready line and error messages), `null` for the class path. */
    private val jarOf: (KtcsExtension) -> Path? = { null },
    /** The state store, opened by the caller; `null` keeps nothing across runs (tests, persistence.durability=OFF). */
    private val durableState: DurableState? = null,
    private val shutdownRequest: ShutdownRequest = ShutdownRequest {},
) {
    private val log = LoggerFactory.getLogger(KernelApplication::class.java)
    private var koin: KoinApplication? = null
    private val context = RealTimeKernelContext()
    private var coreStarted = false

    /** The kernel, once started. */
    val kernel: KernelCore get() = checkNotNull(koin) { "kTCS is not started" }.koin.get()

    /**
     * Starts everything and returns the line announcing readiness (also logged). If anything fails, what was
     * started is stopped again (the web server never listens) and an extension's failure is an [ExtensionException]
     * naming it.
     */
    fun start(): String = try {
        startAll()
    } catch (error: Exception) {
        abandon(error)
        throw ExtensionFailures(extensions, jarOf).explain(error)
    } catch (error: LinkageError) {
        abandon(error)
        throw ExtensionFailures(extensions, jarOf).explain(error)
    }

    private fun startAll(): String {
        loaded.warnings.forEach { log.warn("model {}: {}", loaded.source, it.line()) }
        // Extensions that start at once (the XML channels) are created after the kernel started, so their first
        // request finds it running.
        val app = koinApplication(createEagerInstances = false) {
            // Koin would log a failing definition with its stack trace before start() reports it in one line (naming
            // the extension, with the causes); a failure that is not an extension's keeps its stack trace there.
            slf4jLogger(Level.NONE)
            modules(kernelModule(config, loaded.model, context), applicationModule())
            extensions.forEach { extension -> modules(moduleOf(extension)) }
        }
        koin = app
        val core = app.koin.get<KernelCore>()
        runBlocking {
            context.call {
                durableState?.restoreInto(core)
                core.start()
                durableState?.resumeIn(core)
            }
        }
        coreStarted = true
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
            durableState?.close()
            app.close()
        }
        koin = null
        coreStarted = false
        log.info("kTCS stopped")
    }

    /** Stops what [start] started before it failed; later failures are kept as suppressed ones. */
    private fun abandon(failure: Throwable) {
        val app = koin ?: return
        koin = null
        if (coreStarted) {
            val core = app.koin.get<KernelCore>()
            runCatching { runBlocking { context.call { core.stop() } } }.exceptionOrNull()?.let(failure::addSuppressed)
        }
        coreStarted = false
        runCatching { context.close() }.exceptionOrNull()?.let(failure::addSuppressed)
        runCatching { durableState?.close() }.exceptionOrNull()?.let(failure::addSuppressed)
        runCatching { app.close() }.exceptionOrNull()?.let(failure::addSuppressed)
    }

    private fun applicationModule() = module {
        single { KernelVersion.ofThisBuild() }
        single { WebServerInfo(accessKeyRequired = config[KtcsSettings.webAccessKey].isNotEmpty()) }
        single {
            // The one place the web API reaches into the kernel core: GET /v1/events' buffer listens synchronously.
            val events = get<KernelCore>().events
            WebServer(get(), get(), get(), shutdownRequest, getAll(), KernelEventTap(events::listen))
        }
    }

    private fun moduleOf(extension: KtcsExtension) = try {
        extension.module()
    } catch (error: RuntimeException) {
        throw moduleFailure(extension, error)
    } catch (error: LinkageError) {
        throw moduleFailure(extension, error)
    }

    private fun moduleFailure(extension: KtcsExtension, error: Throwable) = ExtensionException(
        "extension '${extension.name}'${jarOf(extension).from()} failed to provide its module: ${error.describe()}",
        error,
    )

    private fun readyLine(addresses: List<String>): String {
        val model = loaded.model
        val extensionNames = extensions.joinToString { it.name + jarOf(it).from() }.ifEmpty { "none" }
        return "kTCS ready: model '${model.name}' from ${loaded.source} (${model.summary()}); " +
            "${addresses.joinToString("; ")}; extensions: $extensionNames"
    }
}
