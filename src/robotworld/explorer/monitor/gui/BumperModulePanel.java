package robotworld.explorer.monitor.gui;

import java.awt.Color;
import java.awt.GridLayout;
import javax.swing.JPanel;
import javax.swing.JTextField;
import robotworld.core.BumperModule;

/**
 * A bumper module: one field per bumper, green when free, red on contact, grey until known (thesis figure 4.11).
 */
public class BumperModulePanel extends ModulePanel {

    /** Background of a free bumper. */
    public static final Color FREE = new Color(0x7C, 0xD9, 0x7C);
    /** Background of a bumper in contact. */
    public static final Color CONTACT = new Color(0xF0, 0x5A, 0x5A);
    /** Background of a bumper not reported yet. */
    public static final Color UNKNOWN = new Color(0xDD, 0xDD, 0xDD);

    private final JTextField[] sensors = new JTextField[BumperModule.BUMPERS];

    public BumperModulePanel(String moduleName) {
        super("BumperModule", moduleName);
        JPanel grid = new JPanel(new GridLayout(0, 2, 6, 4));
        for (int i = 0; i < sensors.length; i++) {
            sensors[i] = new JTextField("Bumper " + (i + 1), 8); // as the world view and the plots name it
            sensors[i].setEditable(false);
            sensors[i].setBackground(UNKNOWN);
            sensors[i].getAccessibleContext().setAccessibleName("bumper " + (i + 1));
            grid.add(sensors[i]);
        }
        setBody(grid);
    }

    /** Shows every bumper from a contact mask (bit n-1 = bumper n). */
    public void showMask(int mask) {
        for (int i = 0; i < sensors.length; i++) {
            showContact(i + 1, (mask & 1 << i) != 0);
        }
    }

    /** Shows one bumper (1-based). */
    public void showContact(int bumper, boolean contact) {
        if (bumper < 1 || bumper > sensors.length) {
            showProblem("report about bumper " + bumper + ", which this module does not have");
            return;
        }
        JTextField field = sensors[bumper - 1];
        field.setBackground(contact ? CONTACT : FREE);
        field.setText("Bumper " + bumper + (contact ? " contact" : " free"));
    }

    /** The background of bumper {@code bumper} (1-based): {@link #FREE}, {@link #CONTACT} or {@link #UNKNOWN}. */
    public Color colourOf(int bumper) {
        return sensors[bumper - 1].getBackground();
    }
}
