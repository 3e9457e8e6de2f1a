package org.ktcs.kernel.store

import org.ktcs.extension.config.KtcsConfig
import org.ktcs.kernel.config.Durability
import org.ktcs.kernel.config.KtcsSettings
import org.ktcs.kernel.config.PersistenceSettings
import org.ktcs.kernel.config.RecoveryMode
import org.ktcs.kernel.core.KernelCore
import org.slf4j.LoggerFactory
import java.nio.file.Path

/**
 * The kernel's durable state: the store, read at start, put back into the kernel, and kept up to date from the
 * kernel's events by a journal that a writer thread commits. Created before the kernel; [restoreInto] and [resumeIn]
 * run in the kernel context around its start.
 */
class DurableState private constructor(
    store: StateStore,
    private val stored: StoredState,
    durability: Durability,
    private val mode: RecoveryMode,
    groupWaitMicros: Int,
) : AutoCloseable {
    private var kernel: KernelCore? = null

    // A client's mark wakes the writer after the kernel's queued requests (a group commit), once there is a kernel.
    private val journal = StateJournal(
        store,
        durability == Durability.COMMIT,
        groupNanos = groupWaitMicros * 1_000L,
    ) { wake -> kernel?.context?.execute(wake) ?: wake() }
    private var recovery: StateRecovery? = null
    private var recorder: StateRecorder? = null

    /** Puts the stored objects back, then records every change; before the kernel starts. */
    fun restoreInto(core: KernelCore) {
        kernel = core
        recovery = StateRecovery(core, stored, mode).also { it.restore() }
        val lastNotification = stored.notifications.maxOfOrNull { it.first } ?: 0
        recorder = StateRecorder(core, journal, lastNotification).also { core.events.listen(it::onEvent) }
        core.commitThrough(journal)
    }

    /** Continues the orders under way; right after the kernel started. */
    fun resumeIn(core: KernelCore): String {
        val summary = checkNotNull(recovery) { "restoreInto() first" }.resume()
        recorder!!.recordAllVehicles()
        return summary
    }

    override fun close() = journal.close()

    companion object {
        private val log = LoggerFactory.getLogger(DurableState::class.java)

        /** Opens the configured store and reads it; `null` with `persistence.durability=OFF`. */
        fun open(config: KtcsConfig): DurableState? {
            val durability = config[PersistenceSettings.durability]
            if (durability == Durability.OFF) return null
            val started = System.nanoTime()
            val url = config[PersistenceSettings.url]
            val store = if (url.isBlank()) {
                StateStore.embedded(Path.of(config[KtcsSettings.dataDirectory]), durability == Durability.COMMIT)
            } else {
                StateStore.remote(url, config[PersistenceSettings.username], config[PersistenceSettings.password])
            }
            val stored = try {
                StoredState.load(store)
            } catch (error: Exception) {
                store.close()
                throw error
            }
            log.info(
                "state store: {} ({} orders, {} sequences) read in {} ms; durability {}",
                store.description,
                stored.orders.size,
                stored.sequences.size,
                (System.nanoTime() - started) / 1_000_000,
                durability,
            )
            return DurableState(
                store,
                stored,
                durability,
                config[PersistenceSettings.recovery],
                config[PersistenceSettings.groupWait],
            )
        }
    }
}
