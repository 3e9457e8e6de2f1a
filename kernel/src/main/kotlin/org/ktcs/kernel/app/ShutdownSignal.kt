package org.ktcs.kernel.app

import sun.misc.Signal
import java.util.concurrent.CountDownLatch

/**
 * Waits for Ctrl-C (SIGINT) or SIGTERM. Handling the signals ourselves, instead of relying on a shutdown hook,
 * lets the kernel stop in order and the process exit with code 0.
 */
object ShutdownSignal {
    fun await() {
        val latch = CountDownLatch(1)
        listOf("INT", "TERM").forEach { name -> Signal.handle(Signal(name)) { latch.countDown() } }
        latch.await()
    }
}
