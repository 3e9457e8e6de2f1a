package org.ktcs.extension.web

/** What the kernel's web server tells the routes extensions contribute. Bound by the kernel. */
public class WebServerInfo(
    /** Whether web API clients must send the access key (`web.accessKey` is set), so pages can ask for it. */
    public val accessKeyRequired: Boolean,
)
