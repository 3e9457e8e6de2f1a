package org.ktcs.api.kernel

/**
 * A yes/no answer with the reasons for a no, e.g. why a driver refuses an order. An empty [reasons] list means yes.
 */
public data class Explained(val reasons: List<String> = emptyList()) {
    /** Whether the answer is yes. */
    val isYes: Boolean get() = reasons.isEmpty()

    public companion object {
        /** Yes. */
        public val YES: Explained = Explained()

        /** No, because of [reasons]. */
        public fun no(vararg reasons: String): Explained = Explained(reasons.toList())
    }
}
