package org.ktcs.kernel.web

import org.ktcs.extension.config.KtcsConfig
import org.ktcs.kernel.config.TlsSettings
import java.nio.file.Files
import java.nio.file.Path
import java.security.GeneralSecurityException
import java.security.KeyFactory
import java.security.KeyStore
import java.security.PrivateKey
import java.security.cert.Certificate
import java.security.cert.CertificateFactory
import java.security.spec.PKCS8EncodedKeySpec
import java.util.Base64

/** The key and certificate HTTPS serves, from `web.tls.*`: a key store, or a PEM certificate and key. */
class WebTls(val keyStore: KeyStore, val alias: String, val password: CharArray) {
    /** A setting that names a file kTCS cannot use; the message names the setting and the problem. */
    class InvalidTlsSettings(message: String) : IllegalArgumentException(message)

    companion object {
        /** The TLS material `web.tls.*` configures, or `null` for plain HTTP. */
        fun from(config: KtcsConfig): WebTls? {
            val store = config[TlsSettings.keyStore]
            val certificate = config[TlsSettings.certificate]
            val key = config[TlsSettings.privateKey]
            val password = config[TlsSettings.keyStorePassword].toCharArray()
            return when {
                store.isNotEmpty() && (certificate.isNotEmpty() || key.isNotEmpty()) -> throw InvalidTlsSettings(
                    "web.tls.keyStore and web.tls.certificate/web.tls.privateKey exclude each other; set one of them",
                )

                store.isNotEmpty() -> fromKeyStore(Path.of(store), password, config[TlsSettings.keyAlias])

                certificate.isNotEmpty() || key.isNotEmpty() -> fromPem(certificate, key)

                else -> null
            }
        }

        private fun fromKeyStore(file: Path, password: CharArray, alias: String): WebTls {
            val store = guarded("web.tls.keyStore '$file'") {
                val type = if (file.toString().endsWith(".jks", ignoreCase = true)) "JKS" else "PKCS12"
                KeyStore.getInstance(type).apply { Files.newInputStream(file).use { load(it, password) } }
            }
            val chosen = alias.ifEmpty {
                store.aliases().toList().firstOrNull(store::isKeyEntry)
                    ?: throw InvalidTlsSettings("web.tls.keyStore '$file' holds no private key")
            }
            if (!store.isKeyEntry(chosen)) throw InvalidTlsSettings("web.tls.keyStore '$file' has no key '$chosen'")
            return WebTls(store, chosen, password)
        }

        private fun fromPem(certificateFile: String, keyFile: String): WebTls {
            if (certificateFile.isEmpty() || keyFile.isEmpty()) {
                throw InvalidTlsSettings("web.tls.certificate and web.tls.privateKey go together; set both")
            }
            val chain = guarded("web.tls.certificate '$certificateFile'") {
                Files.newInputStream(Path.of(certificateFile)).use {
                    CertificateFactory.getInstance("X.509").generateCertificates(it).toList()
                }
            }
            if (chain.isEmpty()) throw InvalidTlsSettings("web.tls.certificate '$certificateFile' holds no certificate")
            val key = guarded("web.tls.privateKey '$keyFile'") { privateKey(Files.readString(Path.of(keyFile))) }
            val password = CharArray(0)
            val store = KeyStore.getInstance("PKCS12").apply {
                load(null, null)
                setKeyEntry(ALIAS, key, password, chain.toTypedArray<Certificate>())
            }
            return WebTls(store, ALIAS, password)
        }

        private fun privateKey(pem: String): PrivateKey {
            val body = Regex("-----BEGIN PRIVATE KEY-----(.+?)-----END PRIVATE KEY-----", RegexOption.DOT_MATCHES_ALL)
                .find(pem)?.groupValues?.get(1)
                ?: throw InvalidTlsSettings(
                    "expected an unencrypted PKCS#8 key (BEGIN PRIVATE KEY); convert one with " +
                        "'openssl pkcs8 -topk8 -nocrypt -in key.pem -out key-pkcs8.pem'",
                )
            val spec = PKCS8EncodedKeySpec(Base64.getMimeDecoder().decode(body.trim()))
            return listOf("RSA", "EC", "Ed25519").firstNotNullOfOrNull { algorithm ->
                runCatching { KeyFactory.getInstance(algorithm).generatePrivate(spec) }.getOrNull()
            } ?: throw InvalidTlsSettings("not an RSA, EC or Ed25519 key")
        }

        private fun <T> guarded(what: String, block: () -> T): T = try {
            block()
        } catch (error: InvalidTlsSettings) {
            throw InvalidTlsSettings("$what: ${error.message}")
        } catch (error: java.io.IOException) {
            throw InvalidTlsSettings("$what cannot be read: ${error.message ?: error.javaClass.simpleName}")
        } catch (error: GeneralSecurityException) {
            throw InvalidTlsSettings("$what is not usable: ${error.message ?: error.javaClass.simpleName}")
        }

        private const val ALIAS = "ktcs"
    }
}
