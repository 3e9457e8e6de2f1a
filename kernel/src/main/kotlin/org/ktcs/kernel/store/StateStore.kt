package org.ktcs.kernel.store

import org.flywaydb.core.Flyway
import org.slf4j.LoggerFactory
import java.nio.file.Files
import java.nio.file.Path
import java.sql.Connection
import java.sql.DriverManager
import java.sql.SQLException

/**
 * The JDBC side of the store: opens it (creating or migrating the schema), reads all of it at start and writes
 * batches of changes, each in one transaction. Used by one thread at a time: the starting thread, then the writer.
 */
class StateStore private constructor(
    private val connection: Connection,
    val description: String,
    private val flushCommits: Boolean,
) : StoreWriter {
    private val embedded = connection.metaData.databaseProductName.contains("SQLite", ignoreCase = true)
    private var flushing = flushCommits
    private val upserts = StoreTable.entries.associateWith { table ->
        connection.prepareStatement(
            "INSERT INTO ${table.sqlName} (name, body) VALUES (?, ?) ON CONFLICT (name) DO UPDATE SET body = excluded.body",
        )
    }
    private val deletes = StoreTable.entries.associateWith {
        connection.prepareStatement("DELETE FROM ${it.sqlName} WHERE name = ?")
    }

    /**
     * Every row of [table], in the order the database stores them (no order by name: that would read a large table
     * through its index, a page here and there, instead of from start to end), as (name, JSON), handed to [chunk]
     * [FETCH_SIZE] rows at a time: the JSON of 100,000 orders is several times the size of the orders, and must not be
     * held all at once.
     */
    fun rows(table: StoreTable, chunk: (List<Pair<String, String>>) -> Unit) {
        connection.createStatement().use { statement ->
            statement.fetchSize = FETCH_SIZE
            statement.executeQuery("SELECT name, body FROM ${table.sqlName}").use { result ->
                var rows = ArrayList<Pair<String, String>>(FETCH_SIZE)
                while (result.next()) {
                    rows += result.getString(1) to result.getString(2)
                    if (rows.size == FETCH_SIZE) {
                        chunk(rows)
                        rows = ArrayList(FETCH_SIZE) // a chunk is [chunk]'s to keep: it may decode it on another thread
                    }
                }
                if (rows.isNotEmpty()) chunk(rows)
            }
        }
    }

    /**
     * Writes [changes] in one transaction, in their order; with [flush] (and a store opened to flush its commits) the
     * commit returns only once it is on the disk. PostgreSQL flushes every commit, as configured on its server.
     */
    override fun write(changes: Collection<StoreChange>, flush: Boolean) {
        try {
            flushCommitIf(flush && flushCommits)
            changes.forEach(::stage)
            StoreTable.entries.forEach { table ->
                upserts.getValue(table).executeBatch()
                deletes.getValue(table).executeBatch()
            }
            connection.commit()
        } catch (error: Exception) {
            // Nothing of a failed group stays: not its executed rows, nor the rows staged before a value failed to
            // encode (the retry stages them again).
            runCatching { connection.rollback() }
            (upserts.values + deletes.values).forEach { statement -> runCatching { statement.clearBatch() } }
            throw error
        }
    }

    /** SQLite's `synchronous`: FULL fsyncs the write-ahead log at each commit, NORMAL leaves that to a later one. */
    private fun flushCommitIf(flush: Boolean) {
        if (!embedded || flush == flushing) return
        // SQLite refuses the change inside a transaction, and the driver keeps one open while autoCommit is off.
        connection.autoCommit = true
        try {
            connection.createStatement().use { it.execute("PRAGMA synchronous=${if (flush) "FULL" else "NORMAL"}") }
        } finally {
            connection.autoCommit = false
        }
        flushing = flush
    }

    private fun stage(change: StoreChange) {
        when (change) {
            is StoreChange.Put -> upserts.getValue(change.table).run {
                setString(1, change.name)
                setString(2, StateCodec.write(change.value))
                addBatch()
            }

            is StoreChange.Delete -> deletes.getValue(change.table).run {
                setString(1, change.name)
                addBatch()
            }

            is StoreChange.Clear -> {
                // Rows staged before the clear go first, so that the clear sees them.
                upserts.getValue(change.table).executeBatch()
                connection.createStatement().use { it.executeUpdate("DELETE FROM ${change.table.sqlName}") }
            }
        }
    }

    /** Deletes the notifications older than the newest [keep] (their names are zero-padded sequence numbers). */
    override fun trimNotifications(newest: Long, keep: Int) {
        connection.prepareStatement("DELETE FROM notifications WHERE name <= ?").use {
            it.setString(1, notificationKey(newest - keep))
            it.executeUpdate()
        }
        connection.commit()
    }

    override fun close() {
        runCatching { connection.close() }
    }

    companion object {
        private val log = LoggerFactory.getLogger(StateStore::class.java)

        /** The newest schema version this kTCS writes (the last migration's number). */
        const val SCHEMA_VERSION = 1

        /** The name of notification [number]: sorts like the number. */
        fun notificationKey(number: Long): String = "%019d".format(number.coerceAtLeast(0))

        /** The embedded store in [directory], created if there is none. */
        fun embedded(directory: Path, synchronous: Boolean): StateStore {
            val file = directory.resolve(FILE_NAME)
            val existed = Files.exists(file)
            Files.createDirectories(directory)
            val description = "the state store $file"
            val connection = connect(description, "jdbc:sqlite:$file", "", "", existed)
            try {
                connection.createStatement().use { statement ->
                    // Another kTCS holding the store is reported after a second, not after SQLite's default wait.
                    statement.execute("PRAGMA busy_timeout=$BUSY_TIMEOUT_MILLIS")
                    checkIntegrity(statement, description)
                    statement.execute("PRAGMA journal_mode=WAL")
                    statement.execute("PRAGMA synchronous=${if (synchronous) "FULL" else "NORMAL"}")
                    // SQLite checkpoints the WAL into the file every 1,000 pages but keeps the WAL at its largest size;
                    // this cuts it back after a large write (a restart's recovery, a replaced model).
                    statement.execute("PRAGMA journal_size_limit=$WAL_SIZE_LIMIT_BYTES")
                }
            } catch (error: SQLException) {
                connection.close()
                throw unreadable(description, error, existed)
            }
            return open(connection, description, "jdbc:sqlite:$file", "", "", existed, synchronous)
        }

        /** The store at a JDBC [url] (PostgreSQL), its schema created or migrated if needed. */
        fun remote(url: String, user: String, password: String): StateStore {
            val description = "the state store at $url"
            return open(connect(description, url, user, password, true), description, url, user, password, true, true)
        }

        private fun connect(description: String, url: String, user: String, password: String, existed: Boolean) =
            try {
                DriverManager.getConnection(url, user, password)
            } catch (error: SQLException) {
                throw unreadable(description, error, existed)
            }

        private fun open(
            connection: Connection,
            description: String,
            url: String,
            user: String,
            password: String,
            existed: Boolean,
            flushCommits: Boolean,
        ): StateStore = try {
            StoreSchema.ensure(connection, description) { migrate(url, user, password) }
            lockForThisKtcs(connection, description)
            connection.autoCommit = false
            StateStore(connection, description, flushCommits)
        } catch (error: SQLException) {
            connection.close()
            throw unreadable(description, error, existed)
        } catch (error: StoreException) {
            connection.close()
            throw error
        }

        /** One kTCS per store: a second one started on the same store must not write into it. */
        private fun lockForThisKtcs(connection: Connection, description: String) {
            connection.createStatement().use { statement ->
                if (connection.metaData.databaseProductName.contains("SQLite", ignoreCase = true)) {
                    // Held until the connection closes (after the migration, which uses a connection of its own).
                    statement.execute("PRAGMA locking_mode=EXCLUSIVE")
                    statement.execute("BEGIN EXCLUSIVE")
                    statement.execute("COMMIT")
                } else {
                    val locked = statement.executeQuery("SELECT pg_try_advisory_lock($ADVISORY_LOCK)").use {
                        it.next() && it.getBoolean(1)
                    }
                    if (!locked) throw StoreException(inUse(description))
                }
            }
        }

        private fun inUse(description: String) =
            "$description is in use by another kTCS (or another program): stop that one first, or give this one " +
                "another kernel.dataDirectory (or persistence.url)"

        private fun migrate(url: String, user: String, password: String) {
            val started = System.nanoTime()
            Flyway.configure(StateStore::class.java.classLoader)
                .dataSource(url, user, password)
                .locations("classpath:org/ktcs/kernel/store/migration")
                .load()
                .migrate()
            log.info(
                "state store schema migrated to version {} in {} ms",
                SCHEMA_VERSION,
                (System.nanoTime() - started) / 1_000_000,
            )
        }

        private fun checkIntegrity(statement: java.sql.Statement, description: String) {
            statement.executeQuery("PRAGMA quick_check").use { result ->
                val problems = buildList { while (result.next()) add(result.getString(1)) }.filter { it != "ok" }
                if (problems.isNotEmpty()) {
                    throw StoreException("$description is damaged (${problems.take(3).joinToString("; ")}); $RECOVER")
                }
            }
        }

        private fun unreadable(description: String, error: SQLException, existed: Boolean) = if (isBusy(error)) {
            StoreException(inUse(description), error)
        } else {
            damaged(description, error, existed)
        }

        private fun isBusy(error: SQLException) =
            error.message.orEmpty().let { "SQLITE_BUSY" in it || "database is locked" in it }

        private fun damaged(description: String, error: SQLException, existed: Boolean) = StoreException(
            "$description cannot be ${if (existed) "read" else "created"}: ${error.message?.lines()?.first()}; " +
                if (existed) RECOVER else "check the directory's permissions or persistence.url and its credentials",
            error,
        )

        const val FILE_NAME = "state.db"
        const val FETCH_SIZE = 1000
        private const val ADVISORY_LOCK = 18_180_118L
        private const val BUSY_TIMEOUT_MILLIS = 1_000
        private const val WAL_SIZE_LIMIT_BYTES = 8L * 1024 * 1024

        /** What a user can do about a store kTCS refuses to start over. */
        const val RECOVER =
            "kTCS does not start over it, so that no accepted order is lost. Restore it from a backup, or move it " +
                "aside to start with no orders (see the README, section \"Where kTCS keeps its data\")"
    }
}
