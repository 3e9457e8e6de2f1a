package org.ktcs.kernel.extension

import org.koin.core.module.Module

/**
 * A kTCS extension: a vehicle driver, a strategy, a web panel, a channel to host systems. Extensions are found at
 * start-up with [java.util.ServiceLoader]: list the implementing class in
 * `META-INF/services/org.ktcs.kernel.extension.KtcsExtension` of the extension's jar.
 *
 * The kernel loads every extension's [module] after its own, so an extension can replace a default component by
 * declaring a definition of the same type.
 */
interface KtcsExtension {
    /** A short name for logs and error messages. */
    val name: String

    /** The Koin definitions the extension contributes. */
    fun module(): Module
}
