package org.ktcs.kernel.app

import org.koin.core.KoinApplication
import org.koin.dsl.koinApplication
import org.koin.dsl.module
import org.koin.logger.slf4jLogger
import org.ktcs.kernel.config.KtcsConfig
import org.ktcs.kernel.extension.ExtensionException
import org.ktcs.kernel.extension.KtcsExtension
import org.ktcs.kernel.web.KernelVersion
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
) {
    private val log = LoggerFactory.getLogger(KernelApplication::class.java)
    private var koin: KoinApplication? = null

    /** Starts everything and returns the line announcing readiness (also logged). */
    fun start(): String {
        val app = koinApplication {
            slf4jLogger()
            modules(kernelModule())
            extensions.forEach { extension -> modules(moduleOf(extension)) }
        }
        koin = app
        val webAddress = app.koin.get<WebServer>().start()
        val ready = readyLine(webAddress)
        log.info(ready)
        return ready
    }

    fun stop() {
        koin?.let { app ->
            app.koin.get<WebServer>().stop()
            app.close()
        }
        koin = null
        log.info("kTCS stopped")
    }

    private fun kernelModule() = module {
        single { config }
        single { loaded.model }
        single { KernelVersion.ofThisBuild() }
        single { WebServer(get(), get()) }
    }

    private fun moduleOf(extension: KtcsExtension) = try {
        extension.module()
    } catch (error: RuntimeException) {
        throw ExtensionException("extension '${extension.name}' failed to provide its module: ${error.message}", error)
    }

    private fun readyLine(webAddress: String): String {
        val model = loaded.model
        val extensionNames = extensions.joinToString { it.name }.ifEmpty { "none" }
        return "kTCS ready: model '${model.name}' from ${loaded.source} (${model.summary()}); " +
            "web API $webAddress/v1; extensions: $extensionNames"
    }
}
