package org.ktcs.kernel.bench

import java.nio.file.Files
import java.nio.file.Path

/** CPU time and resident memory of a process (and of one named thread of it), read from Linux's `/proc`. */
class ProcStats(private val pid: Long) {
    /** The process's resident set size in MiB (`VmRSS`), or `null` once it is gone. */
    fun rssMib(): Double? = read(Path.of("/proc/$pid/status"))?.lineSequence()
        ?.firstOrNull { it.startsWith("VmRSS:") }
        ?.split(Regex("\\s+"))?.getOrNull(1)?.toLongOrNull()
        ?.let { it / 1024.0 }

    /** User plus system CPU seconds the whole process has used. */
    fun cpuSeconds(): Double = cpuOf(Path.of("/proc/$pid/stat")) ?: 0.0

    /** CPU seconds of the process's threads named [name] (e.g. kTCS's `kernel` thread), `null` if none is. */
    fun threadCpuSeconds(name: String): Double? {
        val tasks = Path.of("/proc/$pid/task")
        val matching = runCatching { Files.list(tasks).use { it.toList() } }.getOrDefault(emptyList())
            .filter { read(it.resolve("comm"))?.trim() == name }
        if (matching.isEmpty()) return null
        return matching.sumOf { cpuOf(it.resolve("stat")) ?: 0.0 }
    }

    /** Every live thread of the process, by thread id: its name (as `comm`, at most 15 characters) and CPU seconds. */
    fun threads(): Map<Long, Pair<String, Double>> {
        val tasks = runCatching { Files.list(Path.of("/proc/$pid/task")).use { it.toList() } }.getOrDefault(emptyList())
        return tasks.mapNotNull { task ->
            val id = task.fileName.toString().toLongOrNull() ?: return@mapNotNull null
            val name = read(task.resolve("comm"))?.trim() ?: return@mapNotNull null
            id to (name to (cpuOf(task.resolve("stat")) ?: 0.0))
        }.toMap()
    }

    private fun cpuOf(stat: Path): Double? {
        val text = read(stat) ?: return null
        // Fields after the command name (which may contain spaces) start at field 3; utime is 14, stime 15.
        val fields = text.substringAfterLast(')').trim().split(' ')
        val ticks = (fields.getOrNull(UTIME)?.toLongOrNull() ?: 0) + (fields.getOrNull(STIME)?.toLongOrNull() ?: 0)
        return ticks / CLOCK_TICKS_PER_SECOND
    }

    private fun read(path: Path): String? = runCatching { Files.readString(path) }.getOrNull()

    companion object {
        private const val UTIME = 11
        private const val STIME = 12

        // USER_HZ is 100 on every Linux architecture the JDK runs on.
        private const val CLOCK_TICKS_PER_SECOND = 100.0

        /** The bench's own process. */
        fun self(): ProcStats = ProcStats(ProcessHandle.current().pid())
    }
}
