package org.ktcs.kernel.config

import org.ktcs.extension.config.Setting
import org.ktcs.extension.config.stringSetting

/** How the web server serves HTTPS (`web.tls.*`); all empty: plain HTTP. Listed in [KtcsSettings.all]. */
object TlsSettings {
    val keyStore = stringSetting(
        "web.tls.keyStore",
        "",
        "PKCS12 or JKS key store with the certificate and key for HTTPS (empty: see web.tls.certificate; " +
            "neither: plain HTTP).",
    )
    val keyStorePassword = stringSetting(
        "web.tls.keyStorePassword",
        "",
        "Password of web.tls.keyStore and of the key in it.",
    )
    val keyAlias = stringSetting(
        "web.tls.keyAlias",
        "",
        "Alias of the key in web.tls.keyStore (empty: the first key in it).",
    )
    val certificate = stringSetting(
        "web.tls.certificate",
        "",
        "PEM file with the HTTPS certificate (chain), used with web.tls.privateKey instead of a key store.",
    )
    val privateKey = stringSetting(
        "web.tls.privateKey",
        "",
        "PEM file with the unencrypted PKCS#8 private key (BEGIN PRIVATE KEY) of web.tls.certificate.",
    )

    val all: List<Setting<*>> = listOf(keyStore, keyStorePassword, keyAlias, certificate, privateKey)
}
