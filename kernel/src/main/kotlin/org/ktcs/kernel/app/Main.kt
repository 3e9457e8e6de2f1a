package org.ktcs.kernel.app

import kotlin.system.exitProcess

fun main(args: Array<String>) {
    val exitCode = Ktcs(System.out, System.err, System.getenv()).run(args.toList())
    exitProcess(exitCode)
}
