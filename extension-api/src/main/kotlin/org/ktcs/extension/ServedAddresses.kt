package org.ktcs.extension

/**
 * Something an extension serves on the network, for the launcher's "kTCS ready" line, e.g. "XML orders tcp://…".
 * Bind an implementation in the extension's Koin module, named (`single<ServedAddresses>(named("my-extension"))`);
 * it is asked once everything has started.
 */
public fun interface ServedAddresses {
    public fun addresses(): List<String>
}
