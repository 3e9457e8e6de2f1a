package org.ktcs.extension

import org.ktcs.api.dispatching.Dispatcher

/**
 * The kernel's own strategies, for an extension that replaces one of them but keeps the default for what it leaves
 * alone (the nearest-vehicle dispatcher example does). Bound by the kernel; ask for it with Koin's `get()`.
 */
public interface KernelDefaults {
    /** A new instance of kTCS's default dispatcher, working on the kernel's dispatch context. */
    public fun dispatcher(): Dispatcher
}
