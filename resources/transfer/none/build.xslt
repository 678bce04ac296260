<?xml version="1.0" encoding="UTF-8"?>
<!--
  none/build.xslt: the Ant build file of a single-participant project. The same file as for xvsm: compile,
  run and clean over src/ and lib/, so it imports that stylesheet (resolved on the class path).
-->
<xsl:stylesheet version="3.0" xmlns:xsl="http://www.w3.org/1999/XSL/Transform">
  <xsl:import href="../xvsm/build.xslt"/>
</xsl:stylesheet>
