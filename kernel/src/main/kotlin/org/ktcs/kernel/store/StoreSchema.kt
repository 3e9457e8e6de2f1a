package org.ktcs.kernel.store

import java.sql.Connection
import java.sql.SQLException

/**
 * Checks the store's schema version with one query and runs the migrations (Flyway) only when it differs from the
 * one this kTCS writes, so that an up-to-date store costs start-up nothing for the migration library.
 */
internal object StoreSchema {
    fun ensure(connection: Connection, description: String, migrate: () -> Unit) {
        val version = installedVersion(connection)
        when {
            version == StateStore.SCHEMA_VERSION -> Unit

            version == null && hasKtcsTables(connection) -> throw StoreException(
                "$description has kTCS's tables but no schema history (flyway_schema_history); it was not made by " +
                    "kTCS or was damaged; ${StateStore.RECOVER}",
            )

            version != null && version > StateStore.SCHEMA_VERSION -> throw StoreException(
                "$description has schema version $version, newer than the version ${StateStore.SCHEMA_VERSION} " +
                    "this kTCS knows: it was written by a newer kTCS. Start that version, or restore a backup made " +
                    "with this one",
            )

            else -> migrate()
        }
    }

    private fun installedVersion(connection: Connection): Int? = try {
        connection.createStatement().use { statement ->
            statement.executeQuery(
                "SELECT version FROM flyway_schema_history WHERE success = TRUE AND version IS NOT NULL",
            ).use { result ->
                buildList { while (result.next()) add(result.getString(1).substringBefore('.').toInt()) }.maxOrNull()
            }
        }
    } catch (missing: SQLException) {
        // PostgreSQL aborts the transaction on a failed statement; autocommit is still on here, so nothing is lost.
        if (tableExists(connection, "flyway_schema_history")) throw missing
        null
    }

    private fun hasKtcsTables(connection: Connection) = tableExists(connection, "transport_orders")

    private fun tableExists(connection: Connection, name: String): Boolean =
        connection.metaData.getTables(null, null, name, null).use { it.next() }
}
