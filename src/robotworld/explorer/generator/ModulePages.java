package robotworld.explorer.generator;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import javax.xml.namespace.QName;
import org.apache.xmlbeans.XmlCursor;
import org.apache.xmlbeans.XmlObject;
import robotworld.description.EnvModuleListType;
import robotworld.description.ModuleClassName;
import robotworld.description.ModuleListType;
import robotworld.description.ModuleType;
import robotworld.description.RobotWorldType;
import robotworld.description.X10ModuleType;

/**
 * The module documentation a generated project gathers in {@code docs/}: the page each module's {@code <DocRef>}
 * names, copied when it is a file of the RobotWorldExplorer documentation, linked when it is a URL, and an index
 * of every module with its field name and page ({@code docs/index.md}).
 *
 * <p>A relative DocRef is looked up under the documentation root (the RobotWorldExplorer home) and only there: a
 * description cannot make the generator copy any other file into a project.
 */
final class ModulePages {

    /** The attribute the stylesheets read: the page of a module, as a project path or a URL. */
    static final QName PAGE_ATTRIBUTE = new QName(GeneratorFunctions.NAMESPACE, "page", "gen");

    /** One module's documentation. */
    record Page(String docRef, String projectPath, Path source, String url) {
        boolean found() {
            return projectPath != null || url != null;
        }

        String shown() {
            return url != null ? url : projectPath;
        }
    }

    /** One line of the index. */
    private record Row(String field, String participant, String module, String moduleClass, String address,
                       Page page) {
    }

    private final Path root;
    private final Map<String, Page> pages = new LinkedHashMap<>();
    private final Set<String> taken = new HashSet<>();
    private final List<Row> rows = new ArrayList<>();

    private ModulePages(Path root) {
        this.root = root.toAbsolutePath().normalize();
    }

    /** Where relative DocRefs are looked up: {@code rwe.home}, else the working directory. */
    static Path defaultRoot() {
        return Path.of(System.getProperty("rwe.home", "."));
    }

    /**
     * Resolves every module's page and marks each module of the prepared world with {@link #PAGE_ATTRIBUTE}.
     * Modules must already carry their {@code gen:field}.
     */
    static ModulePages resolve(RobotWorldType world, Path root) {
        ModulePages pages = new ModulePages(root);
        for (EnvModuleListType environment : world.getEnvironmentArray()) {
            for (X10ModuleType module : environment.getX10ModuleArray()) {
                pages.add(module, environment.getEnvironmentName(), module.getName(),
                        "X10 " + module.getHouseCode() + unitNumber(module.getUnitCode().toString()),
                        module.isSetDocRef() ? module.getDocRef() : null);
            }
            for (ModuleType module : environment.getModuleArray()) {
                pages.add(module, environment.getEnvironmentName(), module.getName(), "bus " + module.getNodeNumber(),
                        module.isSetDocRef() ? module.getDocRef() : null);
            }
        }
        for (ModuleListType robot : world.getRobotDescriptionArray()) {
            for (ModuleType module : robot.getModuleArray()) {
                pages.add(module, robot.getRobotName(), module.getName(), "bus " + module.getNodeNumber(),
                        module.isSetDocRef() ? module.getDocRef() : null);
            }
        }
        return pages;
    }

    private void add(XmlObject module, String participant, String name, String address, String docRef) {
        Page page = docRef == null ? null : pages.computeIfAbsent(docRef, this::page);
        String field;
        try (XmlCursor cursor = module.newCursor()) {
            field = cursor.getAttributeText(new QName(GeneratorFunctions.NAMESPACE, "field"));
            if (page != null && page.found()) {
                cursor.toNextToken();
                cursor.insertAttributeWithValue(PAGE_ATTRIBUTE, page.shown());
            }
        }
        rows.add(new Row(field, participant, name, ModuleClassName.of(module), address, page));
    }

    private Page page(String docRef) {
        if (docRef.contains("://")) {
            return new Page(docRef, null, null, docRef);
        }
        String path = docRef.replaceAll("[#?].*$", "");
        Path source = root.resolve(path).normalize();
        if (path.isEmpty() || !source.startsWith(root) || !Files.isRegularFile(source)) {
            return new Page(docRef, null, null, null);
        }
        String name = source.getFileName().toString();
        String projectPath = "docs/modules/" + name;
        for (int n = 2; !taken.add(projectPath); n++) {
            int dot = name.lastIndexOf('.');
            projectPath = "docs/modules/" + (dot > 0 ? name.substring(0, dot) + "-" + n + name.substring(dot)
                    : name + "-" + n);
        }
        return new Page(docRef, projectPath, source, null);
    }

    /** The files to copy: project path to source file. */
    Map<String, Path> copies() {
        Map<String, Path> copies = new LinkedHashMap<>();
        for (Page page : pages.values()) {
            if (page.source() != null) {
                copies.put(page.projectPath(), page.source());
            }
        }
        return copies;
    }

    /** {@code docs/index.md}: every module of the world with its field, and where its page is. */
    String index(String worldName, String viewpoint) {
        StringBuilder text = new StringBuilder("# Modules of ").append(markdown(worldName)).append("\n\n");
        text.append("Generated by RobotWorldExplorer for the viewpoint ").append(markdown(viewpoint))
                .append(". Every module is a field of the viewpoint's class; its page says what its functions do.\n\n");
        text.append("| field | participant | module | class | address | page |\n|---|---|---|---|---|---|\n");
        Map<String, Boolean> missing = new HashMap<>();
        for (Row row : rows) {
            String page;
            if (row.page() == null) {
                page = "(none given)";
            } else if (row.page().url() != null) {
                page = "<" + markdown(row.page().url()) + ">";
            } else if (row.page().projectPath() != null) {
                String relative = row.page().projectPath().substring("docs/".length());
                page = "[" + markdown(relative.substring(relative.lastIndexOf('/') + 1)) + "](" + relative + ")";
            } else {
                page = "not found: " + markdown(row.page().docRef());
                missing.put(row.page().docRef(), true);
            }
            text.append("| ").append(markdown(row.field())).append(" | ").append(markdown(row.participant()))
                    .append(" | ").append(markdown(row.module())).append(" | ").append(markdown(row.moduleClass()))
                    .append(" | ").append(markdown(row.address())).append(" | ").append(page).append(" |\n");
        }
        if (!missing.isEmpty()) {
            text.append("\nA page marked \"not found\" is not in the RobotWorldExplorer documentation (")
                    .append(markdown(root.toString())).append("); ask the module's vendor for it.\n");
        }
        text.append("\nThe pages link to the rest of the RobotWorldExplorer documentation (runtime.md, bus.md, ...),"
                + " which is in its docs/ folder.\n");
        return text.toString();
    }

    /** Text for a Markdown table cell: one line, no table breaks, no HTML, nothing invisible. */
    private static String markdown(String text) {
        StringBuilder cell = new StringBuilder(text.length());
        text.codePoints().forEach(c -> {
            if (c == '|') {
                cell.append("\\|");
            } else if (c == '<') {
                cell.append("&lt;");
            } else if (c == '>') {
                cell.append("&gt;");
            } else if (c < 0x20 || c == 0x7f) {
                cell.append(' ');
            } else if (JavaSource.isInvisible(c)) {
                cell.append(String.format("[U+%04X]", c));
            } else {
                cell.appendCodePoint(c);
            }
        });
        return cell.toString().strip();
    }

    private static String unitNumber(String unitCode) {
        List<String> units = List.of("ONE", "TWO", "THREE", "FOUR", "FIVE", "SIX", "SEVEN", "EIGHT", "NINE", "TEN",
                "ELEVEN", "TWELVE", "THIRTEEN", "FOURTEEN", "FIFTEEN", "SIXTEEN");
        return Integer.toString(units.indexOf(unitCode) + 1);
    }
}
