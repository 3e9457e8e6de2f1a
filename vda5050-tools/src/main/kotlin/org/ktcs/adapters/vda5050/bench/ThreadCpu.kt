package org.ktcs.adapters.vda5050.bench

import org.ktcs.adapters.vda5050.Vda5050Broker
import org.ktcs.adapters.vda5050.broker.BuiltinBroker
import org.ktcs.kernel.bench.ProcStats

/**
 * kTCS's CPU during a run split by who spent it, from its threads' names: the embedded broker runs in kTCS's process
 * and counts as kTCS's CPU, and this says how much of it is the broker's. A thread that ended during the run is left
 * out (so the groups may add up to a little less than the process's CPU).
 */
internal class ThreadCpu(private val stats: ProcStats) {
    private val start = stats.threads()

    /** CPU seconds per group since this was created, biggest first. */
    fun byGroup(): List<Pair<String, Double>> = stats.threads().entries
        .groupBy({ (_, thread) -> groupOf(thread.first) }) { (id, thread) ->
            thread.second - (start[id]?.second ?: 0.0)
        }
        .mapValues { (_, seconds) -> seconds.sum() }
        .entries.sortedByDescending { it.value }.map { it.key to it.value }

    companion object {
        const val BROKER_GROUP = "MQTT broker"
        const val IN_PROCESS_GROUP = "in-process link + message checks"

        /** The group of a thread named [name]; names are cut to 15 characters by Linux. */
        fun groupOf(name: String): String = when {
            name == "kernel" -> "kernel"

            IN_PROCESS.any { name.startsWith(it) } -> IN_PROCESS_GROUP

            BROKER.any { name.startsWith(it) } -> BROKER_GROUP

            CLIENT.any { name.startsWith(it) } -> "MQTT client + message checks"

            name == Vda5050Broker.SENDING_THREAD -> "orders out (encoding, publishing)"

            name.startsWith("DefaultDispatch") || name.startsWith("ktor") -> "web API"

            name.startsWith("C1 ") || name.startsWith("C2 ") || name.startsWith("GC") || name == "VM Thread" ->
                "JVM (JIT, GC)"

            else -> "other"
        }

        // The builtin broker's event loop (where the driver also reads the vehicles' messages), HiveMQ CE's threads
        // (its event loops, persistence writers and timers) and the HiveMQ MQTT client's.
        private val BROKER = listOf(
            BuiltinBroker.THREAD_NAME,
            "hivemq-",
            "single-writer",
            "payload-persist",
            "Exodus",
            "embedded-hivemq",
            "scheduled-persi",
            "global-traffic",
            "rocksdb",
        )

        // The embedded broker's extension executors: HiveMQ hands every inbound publish to them once an interceptor
        // is registered, and the driver's in-process link validates and parses the vehicles' messages there.
        private val IN_PROCESS = listOf("extension-task", "managed-extensi", "extension-exec", "hivemq-extensio")
        private val CLIENT = listOf("com.hivemq.clie", "RxComputationTh", "RxCachedWorkerP", "RxSchedulerPurg")
    }
}
