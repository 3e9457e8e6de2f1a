package org.ktcs.extension

/** An extension that cannot be loaded or started, or that was set up wrongly; the message names it. */
public class ExtensionException(message: String, cause: Throwable? = null) : RuntimeException(message, cause)
